// Plan -> action tuples (A, C_pre, C_post) of the paper's Section III.D, the
// input of the behavior-tree layer (which knows nothing of LTL).
//
// One tuple per move of the plan (stay steps are dropped: they change
// nothing), prefix first, then the cycle's moves (in_cycle = true; a BT that
// executes the cycle repeats them). For each:
//   pre / post         : the full state before / after — every object's and
//                        container's location, by name (the paper's
//                        "state condition", e.g. {o1 in r1, o2 in r1}),
//   relaxed_pre        : the "action condition": the target object is at its
//                        source; if the source or the destination is a
//                        container, where that container stands,
//   relaxed_post       : the target object is at its destination,
//   hand_before/after  : the hand's location ("home" before the first action).
// Invariant: for consecutive tuples i, i+1 of the prefix, post(i) == pre(i+1).
#pragma once

#include <string>
#include <vector>

#include "rtamp/plan/plan.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::plan {

struct Condition {
  std::string thing;
  std::string location;
  friend bool operator==(const Condition&, const Condition&) = default;
};

struct ActionTuple {
  std::string action;  // "move(o1, r2)"
  std::string thing, from, to;
  std::vector<Condition> pre, post;
  std::vector<Condition> relaxed_pre, relaxed_post;
  std::string hand_before, hand_after;
  double cost = 0;
  bool in_cycle = false;
};

std::vector<ActionTuple> to_action_tuples(const task::System& ts, const Plan& plan);

}  // namespace rtamp::plan
