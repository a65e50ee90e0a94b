// Observers of the reactive loop (reactive_loop.hpp): everything an episode
// shows or records — the JSON Lines log (jsonl_log.hpp), the readable
// timeline (timeline.hpp), tree dumps (tree_dump.hpp), video (episode layer)
// — is an observer attached to the loop, never code inside it.
// Every callback has a no-op default; `t` is world time in seconds. Callbacks
// run on the loop's thread, in the order things happen; they must not call
// back into the loop except through const accessors.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/bt/status.hpp"
#include "rtamp/exec/episode_metrics.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/plan/action_tuple.hpp"
#include "rtamp/plan/plan.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

struct EpisodeInfo {
  std::string scenario, task;
  std::string algorithm, conditions, reconfiguration, world;
  std::uint64_t seed = 0;
  const automata::Automaton* automaton = nullptr;  // the task's, as the planner translated it
};

struct PlanEvent {
  bool first = false;
  const plan::PlanResult& result;
  const std::vector<plan::ActionTuple>& tuples;
  std::vector<std::uint32_t> automaton_states;  // the tracked states it started from
  world::Placement start;                       // the state it started from (its first move's pre-state)
  std::string hand;                             // the hand's location there ("" home)
};

// A new task was taken in (applied) or refused (docs/exec.md "A new task").
struct TaskEvent {
  const world::TaskChange& change;          // the formula, its propositions, who gave it
  bool applied = false;
  std::string refused;                      // why, when not applied
  const automata::Automaton* automaton = nullptr;  // the new task's (applied)
};

class EpisodeObserver {
 public:
  virtual ~EpisodeObserver() = default;
  virtual void on_begin(const EpisodeInfo&) {}
  // A move started, finished, failed or was halted (`what`), with a reason for the last two.
  virtual void on_action(double /*t*/, const char* /*what*/, const std::string& /*action*/,
                         const std::string& /*why*/) {}
  virtual void on_intervention(const WorldEvent&) {}
  // Perception saw a placement different from the one before.
  virtual void on_perceived(double /*t*/, const world::Placement& /*seen*/, const world::Placement& /*before*/) {}
  // Things perceived new or gone: the transition system was updated (Algorithm 1 lines 9-10).
  virtual void on_things_changed(double /*t*/, const std::vector<std::string>& /*added*/,
                                 const std::vector<std::string>& /*removed*/) {}
  // The observed run took a step; `states` are the Büchi states tracked after it.
  virtual void on_progress(double /*t*/, const world::Placement& /*state*/,
                           const std::vector<std::uint32_t>& /*states*/) {}
  // A relocation that a subtree can handle (Algorithm 1 lines 5-8): no replanning.
  virtual void on_handled_by_tree(double /*t*/, const std::string& /*by*/) {}
  virtual void on_replan_request(double /*t*/, const std::string& /*why*/) {}
  virtual void on_plan(double /*t*/, const PlanEvent&) {}
  // A tree change was applied (deferred: it had to wait for a running move), or deferred.
  virtual void on_tree_change(double /*t*/, const ReconfigurationReport&, const PlanTree&, bool /*deferred*/) {}
  virtual void on_cycle(double /*t*/, int /*completed*/) {}
  // A new task was given (applied or refused).
  virtual void on_task(double /*t*/, const TaskEvent&) {}
  // The running move was halted because finishing it would break the new task, or the rule
  // book of space would refuse its place now (`rule` says why).
  virtual void on_redirect(double /*t*/, const std::string& /*action*/, const std::string& /*rule*/) {}
  virtual void on_tick(double /*t*/, bt::Status, const std::string& /*running*/) {}
  virtual void on_end(double /*t*/, const EpisodeMetrics&, const world::Placement& /*final_placement*/) {}
};

}  // namespace rtamp::exec
