// The behavior tree of a logged episode, for a replay's `tree` messages
// (docs/serve.md "Replay"): rebuilt from the log with the code the loop built
// the live tree with. Each `plan` record's moves are replayed from the state
// the plan started from (its "start" placement and "hand") through the task's
// transition system into action tuples (plan::to_action_tuples, as the
// planner makes them), and the tuples into an exec::PlanTree of the episode's
// condition form (the `episode` record's "conditions"). A plan becomes the
// tree when a `tree` record says its change was applied (at once, or — a
// deferred change — at the later `tree` record with "deferred").
//
// Exact: node names, kinds, categories and order are the live tree's (a tree
// reconfigured online holds one subtree per tuple of the latest applied plan,
// in plan order, each updated in place to that tuple: what a fresh build of
// the same tuples is). Statuses are not rebuilt: the tree message's nodes are
// IDLE; the replay sends the log's `statuses` records over them (replay.hpp).
// A log whose `plan` records have no "start" (written before it was logged)
// gets the latest `run` state before the plan as the start (hand "home"): the
// same tree whenever the plan started from the observed state.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/plan/action_tuple.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

class LoggedTree {
 public:
  explicit LoggedTree(world::Scenario scenario);

  // Feeds one record (in log order); `known`: where things were
  // as of this record (classes of added things included). Returns the tree
  // message (tree_message.hpp) when the record changed the tree. A `plan`
  // record whose moves cannot be replayed (a name the scenario cannot have, no
  // start) leaves no plan to apply.
  std::optional<std::string> record(const nlohmann::json& record, double t, const world::Placement& known);

 private:
  world::Scenario scenario_;
  exec::ConditionMode mode_ = exec::ConditionMode::Action;
  std::optional<std::vector<plan::ActionTuple>> planned_;  // the latest plan's tuples
  std::optional<world::Placement> run_;                    // the latest `run` state (locations only)
};

}  // namespace rtamp::serve
