#include "rtamp/plan/action_tuple.hpp"

namespace rtamp::plan {

namespace {
std::vector<Condition> full_state(const task::System& ts, const task::State& s) {
  std::vector<Condition> out;
  out.reserve(ts.num_things());
  for (unsigned t = 0; t < ts.num_things(); ++t) out.push_back({ts.thing_name(t), ts.location_name(ts.location(s, t))});
  return out;
}

void add_tuples(const task::System& ts, const std::vector<Step>& steps, bool in_cycle, std::vector<ActionTuple>& out) {
  for (const Step& st : steps) {
    if (st.action.is_stay()) continue;
    ActionTuple a;
    const unsigned t = st.action.thing;
    a.action = ts.action_name(st.action);
    a.thing = ts.thing_name(t);
    a.from = ts.location_name(ts.location(st.from, t));
    a.to = ts.location_name(st.action.to);
    a.pre = full_state(ts, st.from);
    a.post = full_state(ts, st.to);
    a.relaxed_pre.push_back({a.thing, a.from});
    const auto from_loc = ts.location(st.from, t);
    if (ts.is_container_location(from_loc)) {
      const unsigned c = ts.thing_of_location(from_loc);
      a.relaxed_pre.push_back({ts.thing_name(c), ts.location_name(ts.location(st.from, c))});
    }
    if (ts.is_container_location(st.action.to)) {
      const unsigned c = ts.thing_of_location(st.action.to);
      a.relaxed_pre.push_back({ts.thing_name(c), ts.location_name(ts.location(st.from, c))});
    }
    a.relaxed_post.push_back({a.thing, a.to});
    a.hand_before = ts.location_name(ts.hand(st.from));
    a.hand_after = ts.location_name(ts.hand(st.to));
    a.cost = st.cost;
    a.in_cycle = in_cycle;
    out.push_back(std::move(a));
  }
}
}  // namespace

std::vector<ActionTuple> to_action_tuples(const task::System& ts, const Plan& plan) {
  std::vector<ActionTuple> out;
  add_tuples(ts, plan.prefix, false, out);
  add_tuples(ts, plan.cycle, true, out);
  return out;
}

}  // namespace rtamp::plan
