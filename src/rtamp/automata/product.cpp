#include "rtamp/automata/product.hpp"

#include "rtamp/automata/pair_states.hpp"

namespace rtamp::automata {

Automaton product(const Automaton& a, const Automaton& b) {
  Automaton p;
  p.atoms = a.atoms;
  p.state_based = false;
  const std::uint32_t na = a.edge_sets();
  p.num_sets = na + b.edge_sets();
  detail::PairStates pairs(p);
  p.initial = pairs.intern(a.initial, b.initial);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto [x, y] = pairs[i];
    for (const Edge& ea : a.edges[x])
      for (const Edge& eb : b.edges[y]) {
        const Cube g = ea.guard & eb.guard;
        if (g.is_false()) continue;
        const std::uint32_t d = pairs.intern(ea.dst, eb.dst);
        p.add_edge(static_cast<std::uint32_t>(i), d, g, ea.marks | (eb.marks << na));
      }
  }
  return p;
}

Automaton complement_dba(const Automaton& w) {
  Automaton c;
  c.atoms = w.atoms;
  c.state_based = false;
  c.num_sets = 1;
  const std::uint32_t n = w.num_states();
  for (std::uint32_t i = 0; i < 2 * n; ++i) c.add_state();
  c.initial = w.initial;
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : w.edges[q]) {
      c.add_edge(q, e.dst, e.guard);
      if (w.state_accepting[e.dst]) continue;
      c.add_edge(q, n + e.dst, e.guard);
      if (!w.state_accepting[q]) c.add_edge(n + q, n + e.dst, e.guard, 1);
    }
  return c;
}

}  // namespace rtamp::automata
