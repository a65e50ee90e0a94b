#include "rtamp/automata/degeneralize.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "rtamp/automata/reduce.hpp"

namespace rtamp::automata {

namespace {

// orders[s]: the sets SCC s must see, in the order levels wait for them.
Automaton degeneralize_with(const Automaton& a, const SccInfo& info, const std::vector<bool>& strong,
                            const std::vector<bool>& weak, const std::vector<std::vector<std::uint32_t>>& orders,
                            bool enter_accepting) {
  Automaton out;
  out.atoms = a.atoms;
  out.num_sets = 1;
  out.state_based = true;
  out.name = a.name;
  // (q, level) -> BA state; single-copy states use level 0.
  std::unordered_map<std::uint64_t, std::uint32_t> ids;
  std::vector<std::uint32_t> first_level(a.num_states(), UINT32_MAX);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> todo;
  auto get = [&](std::uint32_t q, std::uint32_t l) {
    const std::uint64_t key = (std::uint64_t{q} << 32) | l;
    auto [it, fresh] = ids.emplace(key, 0);
    if (fresh) {
      const std::uint32_t sq = info.scc_of[q];
      const bool acc = strong[sq] ? l == orders[sq].size() : bool(weak[sq]);
      it->second = out.add_state(acc);
      todo.emplace_back(q, l);
      if (first_level[q] == UINT32_MAX) first_level[q] = l;
    }
    return it->second;
  };
  // Level used when entering strong SCC s from outside (or at the start): the
  // accepting level has the same successors as level 0 and simulates it.
  auto entry = [&](std::uint32_t q) {
    const std::uint32_t s = info.scc_of[q];
    if (!strong[s]) return 0u;
    if (first_level[q] != UINT32_MAX) return first_level[q];
    return enter_accepting ? static_cast<std::uint32_t>(orders[s].size()) : 0u;
  };
  out.initial = get(a.initial, entry(a.initial));
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const auto [q, l] = todo[i];
    const std::uint32_t src = ids.at((std::uint64_t{q} << 32) | l);
    const std::uint32_t sq = info.scc_of[q];
    for (const Edge& e : a.edges[q]) {
      const std::uint32_t sd = info.scc_of[e.dst];
      std::uint32_t dl = 0;
      if (strong[sd]) {
        if (sd != sq) {
          dl = entry(e.dst);
        } else {
          const auto& order = orders[sd];
          const auto k = static_cast<std::uint32_t>(order.size());
          dl = l == k ? 0 : l;
          while (dl < k && (e.marks >> order[dl]) & 1u) ++dl;
        }
      }
      const std::uint32_t d = get(e.dst, dl);
      out.add_edge(src, d, e.guard);
    }
  }
  return out;
}

}  // namespace

std::vector<Automaton> degeneralize_candidates(const Automaton& a) {
  const Marks all = a.all_marks();
  const SccInfo info = scc_decompose(a);
  std::vector<bool> strong(info.count, false), weak(info.count, false);
  bool any_strong = false;
  for (std::uint32_t s = 0; s < info.count; ++s) {
    if (!info.accepting(s, all)) continue;
    weak[s] = true;
  }
  // After canonicalize_acceptance, weak accepting SCCs carry `all` on every
  // internal edge; any other accepting SCC needs levels.
  for (std::uint32_t q = 0; q < a.num_states(); ++q)
    for (const Edge& e : a.edges[q]) {
      const std::uint32_t s = info.scc_of[q];
      if (info.scc_of[e.dst] == s && weak[s] && e.marks != all) {
        weak[s] = false;
        strong[s] = true;
        any_strong = true;
      }
    }
  if (a.num_sets == 0) {
    std::fill(weak.begin(), weak.end(), true);
    std::fill(strong.begin(), strong.end(), false);
    any_strong = false;
  }
  // Per strong SCC, drop sets implied by another inside the SCC: if every
  // internal edge carrying i also carries j, seeing i infinitely often
  // implies seeing j, so j needs no level.
  std::vector<std::vector<std::uint32_t>> needed(info.count);
  {
    // implied[s][i] = marks present on every internal edge of s that carries i.
    std::vector<std::vector<Marks>> implied(info.count, std::vector<Marks>(a.num_sets, all));
    for (std::uint32_t q = 0; q < a.num_states(); ++q)
      for (const Edge& e : a.edges[q]) {
        const std::uint32_t s = info.scc_of[q];
        if (!strong[s] || info.scc_of[e.dst] != s) continue;
        for (std::uint32_t i = 0; i < a.num_sets; ++i)
          if ((e.marks >> i) & 1u) implied[s][i] &= e.marks;
      }
    for (std::uint32_t s = 0; s < info.count; ++s) {
      if (!strong[s]) continue;
      Marks keep = all;
      for (std::uint32_t j = 0; j < a.num_sets; ++j)
        for (std::uint32_t i = 0; i < a.num_sets; ++i)
          if (i != j && ((keep >> i) & 1u) && ((implied[s][i] >> j) & 1u)) {
            keep &= ~(Marks{1} << j);
            break;
          }
      for (std::uint32_t i = 0; i < a.num_sets; ++i)
        if ((keep >> i) & 1u) needed[s].push_back(i);
    }
  }
  std::size_t max_needed = 0;
  for (const auto& n : needed) max_needed = std::max(max_needed, n.size());
  if (!any_strong) {
    std::vector<Automaton> one;
    one.push_back(degeneralize_with(a, info, strong, weak, needed, false));
    return one;
  }
  // Candidate orders: the same permutation of positions applied to every SCC's
  // list (all permutations up to 4 sets, rotations beyond).
  std::vector<std::vector<std::uint32_t>> perms;
  std::vector<std::uint32_t> p(max_needed);
  std::iota(p.begin(), p.end(), 0u);
  if (max_needed <= 1) {
    perms.push_back(p);
  } else if (max_needed <= 4) {
    do perms.push_back(p);
    while (std::next_permutation(p.begin(), p.end()));
  } else {
    for (std::size_t r = 0; r < max_needed; ++r) {
      perms.push_back(p);
      std::rotate(p.begin(), p.begin() + 1, p.end());
    }
  }
  std::vector<Automaton> out;
  for (const auto& perm : perms) {
    std::vector<std::vector<std::uint32_t>> orders(info.count);
    for (std::uint32_t s = 0; s < info.count; ++s) {
      // Apply perm restricted to the positions that exist in this SCC's list.
      for (std::uint32_t pos : perm)
        if (pos < needed[s].size()) orders[s].push_back(needed[s][pos]);
    }
    for (bool enter_accepting : {true, false})
      out.push_back(degeneralize_with(a, info, strong, weak, orders, enter_accepting));
  }
  return out;
}

Automaton degeneralize(const Automaton& a) {
  std::vector<Automaton> c = degeneralize_candidates(a);
  std::size_t best = 0;
  for (std::size_t i = 1; i < c.size(); ++i)
    if (c[i].num_states() < c[best].num_states() ||
        (c[i].num_states() == c[best].num_states() && c[i].num_edges() < c[best].num_edges()))
      best = i;
  return std::move(c[best]);
}

}  // namespace rtamp::automata
