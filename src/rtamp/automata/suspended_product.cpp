#include "rtamp/automata/suspended_product.hpp"

#include "rtamp/automata/pair_states.hpp"
#include "rtamp/automata/reduce.hpp"

namespace rtamp::automata {

namespace {

constexpr std::uint32_t kIdle = ~std::uint32_t{0};  // s not running

}  // namespace

Automaton suspended_product(const Automaton& a, const Automaton& s) {
  const SccInfo scc = scc_decompose(a);
  const Marks all = a.state_based ? 1u : a.all_marks();
  auto running = [&](std::uint32_t q) { return scc.accepting(scc.scc_of[q], all); };
  Automaton p;
  p.atoms = a.atoms;
  p.state_based = false;
  const std::uint32_t na = a.edge_sets();
  p.num_sets = na + s.edge_sets();
  detail::PairStates pairs(p);
  p.initial = pairs.intern(a.initial, running(a.initial) ? s.initial : kIdle);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto [x, y] = pairs[i];
    const auto src = static_cast<std::uint32_t>(i);
    for (const Edge& ea : a.edges[x]) {
      if (!running(ea.dst)) {
        p.add_edge(src, pairs.intern(ea.dst, kIdle), ea.guard, ea.marks);
      } else if (y == kIdle || scc.scc_of[ea.dst] != scc.scc_of[x]) {
        // Entering an accepting SCC: s starts (again) after this letter.
        p.add_edge(src, pairs.intern(ea.dst, s.initial), ea.guard, ea.marks);
      } else {
        for (const Edge& es : s.edges[y]) {
          const Cube g = ea.guard & es.guard;
          if (g.is_false()) continue;
          p.add_edge(src, pairs.intern(ea.dst, es.dst), g, ea.marks | (es.marks << na));
        }
      }
    }
  }
  return p;
}

}  // namespace rtamp::automata
