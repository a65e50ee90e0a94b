#include "rtamp/automata/accepting_cycles.hpp"

#include <cstdint>

namespace rtamp::automata {

namespace {
// Per state: reachable from `from` by >= 1 edge with a satisfiable guard.
std::vector<bool> reach_from(const Automaton& ba, std::uint32_t from) {
  std::vector<bool> seen(ba.num_states(), false);
  std::vector<std::uint32_t> todo{from};
  while (!todo.empty()) {
    const std::uint32_t q = todo.back();
    todo.pop_back();
    for (const auto& e : ba.edges[q])
      if (!e.guard.is_false() && !seen[e.dst]) {
        seen[e.dst] = true;
        todo.push_back(e.dst);
      }
  }
  return seen;
}
// reach[q][p]: p is reachable from q by >= 1 edge.
std::vector<std::vector<bool>> reach_matrix(const Automaton& ba) {
  std::vector<std::vector<bool>> reach(ba.num_states());
  for (std::uint32_t q = 0; q < ba.num_states(); ++q) reach[q] = reach_from(ba, q);
  return reach;
}

// on[q]: q lies on an accepting cycle (the header's definition), given `reach`.
std::vector<bool> on_cycles(const Automaton& ba, const std::vector<std::vector<bool>>& reach) {
  const std::uint32_t n = ba.num_states();
  // scc[q]: the least state of q's strongly connected component.
  std::vector<std::uint32_t> scc(n);
  for (std::uint32_t q = 0; q < n; ++q) {
    scc[q] = q;
    for (std::uint32_t p = 0; p < q; ++p)
      if (reach[q][p] && reach[p][q]) {
        scc[q] = p;
        break;
      }
  }
  std::vector<Marks> inside(n, 0);  // per component: the marks of the edges inside it
  for (std::uint32_t u = 0; u < n; ++u)
    for (const auto& e : ba.edges[u])
      if (!e.guard.is_false() && scc[u] == scc[e.dst]) inside[scc[u]] |= ba.cycle_marks(e);
  std::vector<bool> on(n, false);
  const Marks all = ba.cycle_marks_all();
  for (std::uint32_t q = 0; q < n; ++q) on[q] = reach[q][q] && (inside[scc[q]] & all) == all;
  return on;
}
}  // namespace

std::vector<bool> useful_states(const Automaton& ba) {
  const std::uint32_t n = ba.num_states();
  const std::vector<std::vector<bool>> reach = reach_matrix(ba);
  const std::vector<bool> on = on_cycles(ba, reach);
  std::vector<bool> useful(n, false);
  for (std::uint32_t q = 0; q < n; ++q)
    for (std::uint32_t p = 0; p < n && !useful[q]; ++p) useful[q] = on[p] && (p == q || reach[q][p]);
  return useful;
}

std::vector<bool> states_on_accepting_cycles(const Automaton& ba) { return on_cycles(ba, reach_matrix(ba)); }

}  // namespace rtamp::automata
