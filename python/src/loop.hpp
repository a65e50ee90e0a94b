// The reactive loop for Python (loop.cpp): the World trampoline (a world
// written in Python: the way a user plugs in their robot and perception), the
// conversion of Python placements and of new tasks given from Python.
// worlds.cpp binds the C++ worlds on the same World base.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::python {

// name -> (class, container), from a scenario.
using ClassTable = std::map<std::string, std::pair<std::string, bool>>;
ClassTable class_table(const world::Scenario& s);

// A Placement from a Placement or a {thing: location | (location, cls[, container]) | Thing}
// dict; plain locations take their class from `classes` (else "block", not a container).
world::Placement to_placement(const py::handle& o, const ClassTable& classes);

// New tasks from Python (by "api"): a formula and {name: expression} of new
// propositions. `origin` names the argument in error locations ("set_task" ->
// "set_task(formula)", "set_task(propositions['near'])"); a bad expression is
// rtamp::Error there, the formula is checked by the loop.
using PropositionTexts = std::map<std::string, std::string>;
world::TaskChange task_change(double time, const std::string& formula, const PropositionTexts& propositions,
                              const std::string& origin);
// Scheduled new tasks as Python writes them: (time, formula) or (time, formula, {name: expression}).
using NewTask = std::variant<std::tuple<double, std::string>, std::tuple<double, std::string, PropositionTexts>>;
std::vector<world::TaskChange> task_changes(const std::vector<NewTask>& tasks);
std::vector<NewTask> new_tasks(const std::vector<world::TaskChange>& changes);

}  // namespace rtamp::python
