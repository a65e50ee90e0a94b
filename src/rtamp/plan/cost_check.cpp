#include "rtamp/plan/cost_check.hpp"

#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"

namespace rtamp::plan {

namespace {
std::string model_returned(const MotionCostModel& model, double v) {
  return "motion-cost model '" + model.name() + "' returned " + format_number(v, 6);
}
}  // namespace

void throw_bad_cost(const MotionCostModel& model, const task::System& ts, const task::State& s, const task::Action& a,
                    double c) {
  const std::string& thing = ts.thing_name(a.thing);
  throw Error(model_returned(model, c) + " for " + ts.action_name(a) + " (" + thing + " from " +
              ts.location_name(ts.location(s, a.thing)) + ", hand at " + ts.hand_name(s) +
              "): a cost must be >= 0 (+inf: the move is impossible)");
}

void throw_bad_lower_bound(const MotionCostModel& model, const task::System& ts, const task::State& s, unsigned thing,
                           int to, double b) {
  const std::string where = to < 0 ? "anywhere" : ts.location_name(static_cast<unsigned>(to));
  throw Error(model_returned(model, b) + " as lower_bound for bringing " + ts.thing_name(thing) + " from " +
              ts.location_name(ts.location(s, thing)) + " to " + where + " (hand at " + ts.hand_name(s) +
              "): a lower bound must be finite and >= 0 (0 is always correct)");
}

void throw_bad_bound(const MotionCostModel& model, const std::string& what, double b) {
  throw Error(model_returned(model, b) + " as " + what + ": a bound must be finite and >= 0 (0 is always correct)");
}

}  // namespace rtamp::plan
