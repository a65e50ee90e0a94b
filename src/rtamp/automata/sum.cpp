#include "rtamp/automata/sum.hpp"

#include <algorithm>

namespace rtamp::automata {

namespace {

// Marks of an edge of an automaton with `own` sets, padded to `all` sets.
Marks pad(Marks m, std::uint32_t own, std::uint32_t all) {
  const Marks extra = Automaton::marks_below(all) & ~Automaton::marks_below(own);
  if (own == 0 || (m >> (own - 1) & 1u)) m |= extra;
  return m;
}

}  // namespace

Automaton sum(const Automaton& a, const Automaton& b) {
  Automaton s;
  s.atoms = a.atoms;
  s.state_based = false;
  const std::uint32_t na = a.edge_sets(), nb = b.edge_sets();
  s.num_sets = std::max(na, nb);
  s.initial = s.add_state();
  auto copy = [&s](const Automaton& x, std::uint32_t own) {
    const std::uint32_t base = s.num_states();
    for (std::uint32_t q = 0; q < x.num_states(); ++q) s.add_state();
    for (std::uint32_t q = 0; q < x.num_states(); ++q)
      for (const Edge& e : x.edges[q]) s.add_edge(base + q, base + e.dst, e.guard, pad(e.marks, own, s.num_sets));
    for (const Edge& e : x.edges[x.initial]) s.add_edge(s.initial, base + e.dst, e.guard, pad(e.marks, own, s.num_sets));
  };
  copy(a, na);
  copy(b, nb);
  return s;
}

}  // namespace rtamp::automata
