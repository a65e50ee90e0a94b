#include "rtamp/automata/lasso_accept.hpp"

#include <algorithm>

#include "rtamp/util/error.hpp"

namespace rtamp::automata {

bool lasso_accept(const Automaton& a, const LassoWord& w) {
  if (w.cycle.empty()) throw Error("lasso word with an empty cycle", {}, {});
  const std::size_t P = w.prefix.size() + w.cycle.size();
  const std::uint32_t n = a.num_states();
  if (n == 0) return false;
  auto letter = [&](std::size_t i) { return i < w.prefix.size() ? w.prefix[i] : w.cycle[i - w.prefix.size()]; };
  auto next_pos = [&](std::size_t i) { return i + 1 < P ? i + 1 : w.prefix.size(); };
  const Marks all = a.all_marks();
  const std::size_t N = std::size_t{n} * P;
  auto node = [&](std::uint32_t q, std::size_t i) { return std::size_t{q} * P + i; };
  // Iterative Tarjan over reachable product nodes.
  constexpr std::uint32_t kNone = UINT32_MAX;
  std::vector<std::uint32_t> index(N, kNone), low(N, 0);
  std::vector<char> on_stack(N, 0);
  std::vector<std::size_t> stack;
  struct Frame { std::size_t v; std::uint32_t e; };
  std::vector<Frame> call;
  std::uint32_t next_index = 0;
  const std::size_t root = node(a.initial, 0);
  index[root] = low[root] = next_index++;
  stack.push_back(root);
  on_stack[root] = 1;
  call.push_back({root, 0});
  while (!call.empty()) {
    Frame& fr = call.back();
    const std::uint32_t q = static_cast<std::uint32_t>(fr.v / P);
    const std::size_t i = fr.v % P;
    const auto& out = a.edges[q];
    if (fr.e < out.size()) {
      const Edge& e = out[fr.e++];
      if (!e.guard.matches(letter(i))) continue;
      const std::size_t d = node(e.dst, next_pos(i));
      if (index[d] == kNone) {
        index[d] = low[d] = next_index++;
        stack.push_back(d);
        on_stack[d] = 1;
        call.push_back({d, 0});
      } else if (on_stack[d]) {
        low[fr.v] = std::min(low[fr.v], index[d]);
      }
      continue;
    }
    const std::size_t v = fr.v;
    call.pop_back();
    if (!call.empty()) low[call.back().v] = std::min(low[call.back().v], low[v]);
    if (low[v] != index[v]) continue;
    // Pop the SCC rooted at v; collect it.
    std::vector<std::size_t> members;
    std::size_t s;
    do {
      s = stack.back();
      stack.pop_back();
      on_stack[s] = 0;
      members.push_back(s);
      low[s] = index[v];  // SCC id = root index (used below)
    } while (s != v);
    // Internal edges: both ends in this SCC (popped, and low == this root's
    // index, which no other popped SCC has).
    Marks seen = 0;
    bool cycle = false;
    for (std::size_t m : members) {
      const std::uint32_t mq = static_cast<std::uint32_t>(m / P);
      const std::size_t mi = m % P;
      for (const Edge& e : a.edges[mq]) {
        if (!e.guard.matches(letter(mi))) continue;
        const std::size_t d = node(e.dst, next_pos(mi));
        if (index[d] != kNone && !on_stack[d] && low[d] == index[v]) {
          cycle = true;
          seen |= e.marks;
        }
      }
    }
    if (cycle && (seen & all) == all) return true;
  }
  return false;
}

}  // namespace rtamp::automata
