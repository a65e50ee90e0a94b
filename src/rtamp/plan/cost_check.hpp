// The check of every value the planner takes from a motion-cost model
// (plan/motion_cost.hpp), in one place:
//  - a cost must be >= 0 (NaN and negative costs are errors: a negative edge
//    makes a best-first search re-open nodes without end); +infinity is a
//    move the model cannot do (the ik model's unreachable poses), and the
//    product graph gives it no edge;
//  - a bound (lower_bound, transport_bound, carry_bound) must be finite and
//    >= 0 (0 is always correct; a NaN or infinite bound would prune plans
//    that exist).
// A bad value throws rtamp::Error naming the model, what it was asked (the
// edge: action, thing, from, to, hand) and the value, e.g.
//   motion-cost model 'mine' returned -1 for move(o1, r2) (o1 from r1, hand at
//   home): a cost must be >= 0 (+inf: the move is impossible)
// The call sites (product_graph.cpp, heuristic.cpp, chain_bound.cpp) test a
// value with valid_cost / valid_bound, one compare; only a bad value builds a
// message (the throw_* functions, out of line).
#pragma once

#include <limits>
#include <string>

#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::plan {

inline bool valid_cost(double c) { return c >= 0; }  // false for NaN
inline bool valid_bound(double b) { return b >= 0 && b <= std::numeric_limits<double>::max(); }

// cost() returned `c` for action a in state s.
[[noreturn]] void throw_bad_cost(const MotionCostModel& model, const task::System& ts, const task::State& s,
                                 const task::Action& a, double c);
// lower_bound() returned `b` for bringing `thing` (where it is in s, the hand
// where s has it) to location `to` (-1: anywhere).
[[noreturn]] void throw_bad_lower_bound(const MotionCostModel& model, const task::System& ts, const task::State& s,
                                        unsigned thing, int to, double b);
// Another bound: `what` says which and for what, e.g. "carry_bound from r1 to r2".
[[noreturn]] void throw_bad_bound(const MotionCostModel& model, const std::string& what, double b);

}  // namespace rtamp::plan
