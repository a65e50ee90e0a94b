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
}  // namespace

std::vector<bool> useful_states(const Automaton& ba) {
  const std::uint32_t n = ba.num_states();
  const std::vector<std::vector<bool>> reach = reach_matrix(ba);
  std::vector<bool> useful(n, false);
  for (std::uint32_t qa = 0; qa < n; ++qa) {
    if (!ba.is_accepting_state(qa) || !reach[qa][qa]) continue;  // not an accepting state on a cycle
    for (std::uint32_t q = 0; q < n; ++q) useful[q] = useful[q] || q == qa || reach[q][qa];
  }
  return useful;
}

std::vector<bool> states_on_accepting_cycles(const Automaton& ba) {
  const std::uint32_t n = ba.num_states();
  const std::vector<std::vector<bool>> reach = reach_matrix(ba);
  std::vector<bool> on(n, false);
  for (std::uint32_t qa = 0; qa < n; ++qa) {
    if (!ba.is_accepting_state(qa)) continue;
    for (std::uint32_t q = 0; q < n; ++q) on[q] = on[q] || (reach[q][qa] && reach[qa][q]);
  }
  return on;
}

}  // namespace rtamp::automata
