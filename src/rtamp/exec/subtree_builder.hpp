// Plan action tuples -> behavior-tree subtrees, in the two forms of the paper's
// Fig. 3 (Section III.D "Automatic tree construction").
//
// Both forms read the believed placement (world::Placement, blackboard key
// kPlacementKey, refreshed by perception every tick) and run the move through
// an ActionRunner (the simulation's skills, or a fake in tests).
//
//  state condition (Fig. 3a)               action condition (Fig. 3b)
//  ReactiveFallback "move(o1, r2)"          Chooser "move(o1, r2)"
//  ├─ Condition post  (full state)         ├─ Condition post (o1 in r2 [+ tray's region])
//  └─ ReactiveSequence                      └─ Sequence (memory)
//     ├─ Fallback                              ├─ Condition pre (o1 in r1 [+ tray's region])
//     │  ├─ Condition pre (full state)         └─ Move o1 -> r2   (not interruptible)
//     │  └─ Condition running C_R
//     └─ StateUpdate
//        └─ Move o1 -> r2   (not interruptible)
//
// C_R (the running condition) is the pre-state with the target "in hand".
// The state form is reactive: any change of an unrelated thing fails its
// conditions mid-action. The action form's Chooser commits to the running
// branch, so an action in progress completes (its own post/pre are not
// re-checked while it runs). StateUpdate writes the post-state into the
// believed placement as soon as the move succeeds.
// Invariant: update_subtree() changes conditions in place (ports and
// predicates), never ids or structure — Algorithm 2's "update conditions".
#pragma once

#include <memory>
#include <string>

#include "rtamp/bt/bt.hpp"
#include "rtamp/plan/action_tuple.hpp"
#include "rtamp/util/names_table.hpp"
#include "rtamp/world/placement.hpp"

namespace rtamp::exec {

inline constexpr const char* kPlacementKey = "placement";
inline constexpr const char* kInHand = "hand";  // location of a held thing (same as sim::kInHand)

enum class ConditionMode { State, Action };
const NameTable<ConditionMode>& condition_modes();  // state action
const char* to_string(ConditionMode m);

// Runs one move on the robot; called by the Move action node.
class ActionRunner {
 public:
  virtual ~ActionRunner() = default;
  virtual bt::Status start(const plan::ActionTuple& t) = 0;
  virtual bt::Status running(const plan::ActionTuple& t) = 0;
  virtual void halt(const plan::ActionTuple& t) = 0;
};

// True if every condition holds in the placement. A condition on a thing that is
// not in the placement fails.
bool holds(const std::vector<plan::Condition>& conditions, const world::Placement& placement);

std::unique_ptr<bt::Node> build_subtree(const plan::ActionTuple& t, ConditionMode mode, ActionRunner& runner);
// Replaces the conditions (and the move's parameters) of a subtree built by
// build_subtree for a tuple with the same action.
void update_subtree(bt::Node& subtree, const plan::ActionTuple& t, ConditionMode mode, ActionRunner& runner);

// The precondition a subtree checks (relaxed or full), for Algorithm 1's
// "is there a subtree whose precondition holds" test.
const std::vector<plan::Condition>& precondition(const plan::ActionTuple& t, ConditionMode mode);

std::string to_string(const std::vector<plan::Condition>& conditions);

}  // namespace rtamp::exec
