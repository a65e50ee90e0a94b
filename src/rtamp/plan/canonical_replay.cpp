// Replays a canonical lasso on concrete states (plan/canonical_replay.hpp).
#include "rtamp/plan/canonical_replay.hpp"

namespace rtamp::plan {

Plan replay_lasso(const ProductGraph& g, const LassoResult& r) {
  const task::System& ts = g.system();
  Plan p;
  task::State concrete = ts.initial();
  auto add_steps = [&](NodeId cur, const std::vector<std::uint32_t>& edges, std::vector<Step>& out) {
    for (std::uint32_t e : edges) {
      const ProductEdge& pe = g.edge(e);
      task::Action a = task::Action::unpack(pe.action);
      if (!a.is_stay() && ts.group_of(a.thing) >= 0) {
        const std::uint32_t at = ts.location(g.state(cur), a.thing);
        for (unsigned t = 0; t < ts.num_things(); ++t)
          if (ts.group_of(t) == ts.group_of(a.thing) && ts.location(concrete, t) == at) {
            a.thing = static_cast<std::uint16_t>(t);
            break;
          }
      }
      Step st;
      st.action = a;
      st.from = concrete;
      concrete = ts.successor(concrete, a);
      st.to = concrete;
      st.ba_from = g.ba_state(cur);
      st.ba_to = g.ba_state(pe.dst);
      st.cost = pe.cost;
      st.label = g.label(cur);
      out.push_back(st);
      cur = pe.dst;
    }
  };
  p.prefix.reserve(r.prefix_edges.size());
  p.cycle.reserve(r.cycle_edges.size());
  add_steps(r.start, r.prefix_edges, p.prefix);
  add_steps(r.cycle_start, r.cycle_edges, p.cycle);
  p.prefix_cost = r.prefix_cost;
  p.cycle_cost = r.cycle_cost;
  return p;
}

}  // namespace rtamp::plan
