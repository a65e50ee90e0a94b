// Replays a canonical lasso on concrete states (plan/canonical_replay.hpp).
#include "rtamp/plan/canonical_replay.hpp"

#include <vector>

namespace rtamp::plan {

Plan replay_lasso(const ProductGraph& g, const LassoResult& r) {
  const task::System& ts = g.system();
  Plan p;
  task::State concrete = ts.initial();
  std::vector<unsigned> src(ts.num_things());
  auto add_steps = [&](NodeId cur, const std::vector<std::uint32_t>& edges, std::vector<Step>& out) {
    for (std::uint32_t e : edges) {
      const ProductEdge& pe = g.edge(e);
      task::Action a = task::Action::unpack(pe.action);
      // Canonical containers and their locations as the concrete ones.
      ts.canonical_sources(concrete, src.data());
      auto concrete_location = [&](std::uint32_t l) {
        return ts.interchangeable_location(l) ? ts.location_of_container(src[ts.thing_of_location(l)]) : l;
      };
      if (!a.is_stay()) a.to = static_cast<std::uint16_t>(concrete_location(a.to));
      if (!a.is_stay() && ts.container_group_of(a.thing) >= 0) a.thing = static_cast<std::uint16_t>(src[a.thing]);
      if (!a.is_stay() && ts.group_of(a.thing) >= 0) {
        const std::uint32_t at = concrete_location(ts.location(g.state(cur), a.thing));
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
