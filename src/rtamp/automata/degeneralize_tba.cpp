#include "rtamp/automata/degeneralize_tba.hpp"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "rtamp/automata/reduce.hpp"

namespace rtamp::automata {

namespace {

Automaton with_order(const Automaton& a, const SccInfo& info, const std::vector<std::uint32_t>& order) {
  Automaton out;
  out.atoms = a.atoms;
  out.num_sets = 1;
  out.state_based = false;
  out.name = a.name;
  const auto k = static_cast<std::uint32_t>(order.size());
  std::unordered_map<std::uint64_t, std::uint32_t> ids;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> todo;
  auto get = [&](std::uint32_t q, std::uint32_t l) {
    auto [it, fresh] = ids.emplace((std::uint64_t{q} << 32) | l, 0);
    if (fresh) {
      it->second = out.add_state();
      todo.emplace_back(q, l);
    }
    return it->second;
  };
  out.initial = get(a.initial, 0);
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const auto [q, l] = todo[i];
    const std::uint32_t src = ids.at((std::uint64_t{q} << 32) | l);
    for (const Edge& e : a.edges[q]) {
      std::uint32_t dl = 0;
      Marks acc = 0;
      if (info.scc_of[e.dst] == info.scc_of[q]) {
        dl = l;
        while (dl < k && ((e.marks >> order[dl]) & 1u)) ++dl;
        if (dl == k) acc = 1, dl = 0;
      }
      const std::uint32_t d = get(e.dst, dl);
      out.add_edge(src, d, e.guard, acc);
    }
  }
  return out;
}

}  // namespace

Automaton degeneralize_tba(const Automaton& in) {
  Automaton a = in;
  if (a.state_based) {  // an edge accepts when it leaves an accepting state
    a.state_based = false;
    for (std::uint32_t q = 0; q < a.num_states(); ++q)
      for (Edge& e : a.edges[q]) e.marks = a.state_accepting[q] ? 1u : 0u;
    a.num_sets = 1;
  }
  std::fill(a.state_accepting.begin(), a.state_accepting.end(), false);
  canonicalize_acceptance(a, false);  // no marks between SCCs; 0 sets if every cycle accepts
  const SccInfo info = scc_decompose(a);
  if (a.num_sets == 0) {  // every cycle accepts: every edge inside an SCC
    for (std::uint32_t q = 0; q < a.num_states(); ++q)
      for (Edge& e : a.edges[q]) e.marks = info.scc_of[e.dst] == info.scc_of[q] ? 1u : 0u;
    a.num_sets = 1;
  }
  if (a.num_sets == 1) return a;
  std::vector<std::uint32_t> order(a.num_sets);
  for (std::uint32_t i = 0; i < a.num_sets; ++i) order[i] = i;
  Automaton best = with_order(a, info, order);
  for (std::uint32_t r = 1; r < a.num_sets; ++r) {
    std::rotate(order.begin(), order.begin() + 1, order.end());
    Automaton c = with_order(a, info, order);
    if (c.num_states() < best.num_states() ||
        (c.num_states() == best.num_states() && c.num_edges() < best.num_edges()))
      best = std::move(c);
  }
  return best;
}

Automaton state_based_form(const Automaton& a) {
  if (a.state_based) return a;
  Automaton out;
  out.atoms = a.atoms;
  out.name = a.name;
  out.state_based = true;
  out.num_sets = 1;
  const std::uint32_t n = a.num_states();
  for (std::uint32_t q = 0; q < n; ++q) out.add_state(false);
  out.initial = a.initial;
  std::vector<std::uint32_t> copy(n, UINT32_MAX);
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : a.edges[q])
      if (a.accepting_edge(e) && copy[e.dst] == UINT32_MAX) copy[e.dst] = out.add_state(true);
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : a.edges[q]) {
      const std::uint32_t d = a.accepting_edge(e) ? copy[e.dst] : e.dst;
      out.add_edge(q, d, e.guard);
      if (copy[q] != UINT32_MAX) out.add_edge(copy[q], d, e.guard);
    }
  return out;
}

}  // namespace rtamp::automata
