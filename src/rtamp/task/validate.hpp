// The one input check of a scenario, run by every entry point before anything
// runs (rtamp plan / run / batch / sim / gen, plan::Planner, the Python
// module): world::validate() — the scenario's names, geometry, propositions
// and operator script (world/validate.hpp) — and the LTL task (paper Section
// II: φ over the atomic propositions Π).
//
// The task must parse (ltl/parser.hpp), and every atom must be either the name
// of a proposition of the scenario or, written in double quotes, a proposition
// expression (world/propositions.hpp) whose names the scenario defines (things
// and classes at the start or added by its operator script, regions,
// containers: world/names.hpp) — the same rules as for `propositions:`. An
// atom is resolved as the planner's labeling resolves it (task/labeling.hpp):
// a proposition name first, else an expression.
//
// Errors are rtamp::Error located inside the task text (the scenario file's
// line and column when the scenario records where its task starts, else
// "<task>:1:COL"), with the task's line and a caret under the offending word
// as detail, and a did-you-mean where one fits.
#pragma once

#include "rtamp/world/scenario.hpp"

namespace rtamp::task {

// Checks the task of `s` and the new tasks of its operator script
// (s.task_changes: validate_task_changes) (assumes the rest of `s` is valid).
void validate_task(const world::Scenario& s);

// The scenario with the new task `c` in force (docs/exec.md "A new task"):
// `c.task` as its task, `c.propositions` joined to its own (one the scenario
// already defines with the same expression is kept once; another expression
// for a defined name is refused: a new task may add propositions, not change
// them), checked like a scenario's own propositions and task, and a time
// finite and >= 0. Throws rtamp::Error located in `c`, its message naming
// the task change ("new task at t = 12 s: ...").
world::Scenario with_task(const world::Scenario& s, const world::TaskChange& c);

// Every task change of `changes` in order, each on the scenario the ones
// before it made (with_task). Throws the first error.
void validate_task_changes(const world::Scenario& s, const std::vector<world::TaskChange>& changes);

// world::validate(s), then validate_task(s).
void validate(const world::Scenario& s);

}  // namespace rtamp::task
