// Python-side views of planning results: a plan::PlanResult
// with every step named ("move(o1, r2)", states as "o1@r1 o2@r3 hand@r2") and
// its action tuples (plan/action_tuple.hpp), made while the planner that
// produced it is at hand, so a Python user never needs the TS to read a plan.
// Invariant: view.actions are to_action_tuples(planner.system(), result.plan).
#pragma once

#include <string>
#include <vector>

#include "rtamp/plan/planner.hpp"

namespace rtamp::python {

struct StepView {
  std::string action;  // "move(o1, r2)" or "stay"
  std::string thing, to;
  std::string from_state, to_state;
  std::uint32_t ba_from = 0, ba_to = 0;
  double cost = 0;
  std::vector<std::string> label;  // atoms true in the state the step leaves
  std::uint32_t packed = 0;        // task::Action::packed(), for Planner.execute
};

struct PlanView {
  bool found = false;
  std::string reason;  // "none" when found
  std::string message;
  std::vector<StepView> prefix, cycle;
  double prefix_cost = 0, cycle_cost = 0;
  std::vector<plan::ActionTuple> actions;
  plan::SearchStats stats;
  std::vector<std::uint32_t> automaton_states;  // the states the plan started from
};

PlanView make_view(plan::Planner& planner, const plan::PlanResult& r);

}  // namespace rtamp::python
