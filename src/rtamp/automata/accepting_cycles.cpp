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

// Calls f(u, v) for every accepting edge u -> v that can hold.
template <class F>
void for_each_accepting_edge(const Automaton& ba, F f) {
  for (std::uint32_t u = 0; u < ba.num_states(); ++u)
    for (const auto& e : ba.edges[u])
      if (!e.guard.is_false() && ba.accepting_edge(e)) f(u, e.dst);
}
}  // namespace

std::vector<bool> useful_states(const Automaton& ba) {
  const std::uint32_t n = ba.num_states();
  const std::vector<std::vector<bool>> reach = reach_matrix(ba);
  std::vector<bool> useful(n, false);
  for_each_accepting_edge(ba, [&](std::uint32_t u, std::uint32_t v) {
    if (u != v && !reach[v][u]) return;  // not on a cycle
    for (std::uint32_t q = 0; q < n; ++q) useful[q] = useful[q] || q == u || reach[q][u];
  });
  return useful;
}

std::vector<bool> states_on_accepting_cycles(const Automaton& ba) {
  const std::uint32_t n = ba.num_states();
  const std::vector<std::vector<bool>> reach = reach_matrix(ba);
  std::vector<bool> on(n, false);
  for_each_accepting_edge(ba, [&](std::uint32_t u, std::uint32_t v) {
    for (std::uint32_t q = 0; q < n; ++q)
      on[q] = on[q] || ((q == u || reach[q][u]) && (q == v || reach[v][q]));
  });
  return on;
}

}  // namespace rtamp::automata
