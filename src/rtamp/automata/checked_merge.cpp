#include "rtamp/automata/checked_merge.hpp"

#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/product.hpp"
#include "rtamp/automata/reduce.hpp"
#include "rtamp/automata/simulation_reduction.hpp"

namespace rtamp::automata {

namespace {

constexpr std::uint32_t kMaxStates = 64;              // of `a`, for the pairwise attempts
constexpr std::uint64_t kMaxProductStates = 200'000;  // |a| × |negation| bound per check

// `a` with every edge into q (and the start) sent to r; q becomes unreachable.
Automaton redirected(const Automaton& a, std::uint32_t q, std::uint32_t r) {
  Automaton b = a;
  if (b.initial == q) b.initial = r;
  for (std::uint32_t s = 0; s < b.num_states(); ++s) {
    if (s == q) continue;
    for (Edge& e : b.edges[s])
      if (e.dst == q) e.dst = r;
  }
  b.edges[q].clear();
  remove_useless(b);
  merge_parallel_edges(b);
  return b;
}

}  // namespace

bool merge_checked(Automaton& a, const std::function<const Automaton*()>& negation, int attempts) {
  bool merged = false;
  while (attempts > 0) {
    const std::uint32_t n = a.num_states();
    if (n < 2 || n > kMaxStates) break;
    for (const auto& out : a.edges)
      if (out.empty()) return merged;  // empty language or useless states: nothing to gain
    const std::vector<std::vector<bool>> sim = direct_simulation(a);
    bool found = false;
    for (std::uint32_t q = 0; q < n && !found && attempts > 0; ++q)
      for (std::uint32_t r = 0; r < n && attempts > 0; ++r) {
        if (q == r || !sim[q][r] || sim[r][q]) continue;
        const Automaton* neg = negation();
        if (!neg || std::uint64_t{n} * neg->num_states() > kMaxProductStates) return merged;
        Automaton b = redirected(a, q, r);
        if (b.num_states() >= n) continue;
        if (!is_empty(product(b, *neg))) {
          --attempts;
          continue;
        }
        a = std::move(b);
        merged = found = true;
        break;
      }
    if (!found) break;
  }
  return merged;
}

}  // namespace rtamp::automata
