// Random automata and a brute-force acceptance oracle shared by
// lasso_accept_test and emptiness_test.
#pragma once

#include <deque>
#include <random>
#include <set>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/automata/lasso_accept.hpp"

namespace rtamp::automata::test {

inline Automaton random_automaton(std::mt19937_64& rng, std::uint32_t states, std::uint32_t atoms, std::uint32_t sets,
                                  bool state_based, double density) {
  Automaton a;
  for (std::uint32_t i = 0; i < atoms; ++i) a.atom_index(std::string(1, static_cast<char>('a' + i)));
  a.num_sets = state_based ? 1 : sets;
  a.state_based = state_based;
  std::uniform_real_distribution<double> u(0, 1);
  for (std::uint32_t q = 0; q < states; ++q) a.add_state(state_based && u(rng) < 0.4);
  for (std::uint32_t q = 0; q < states; ++q)
    for (std::uint32_t d = 0; d < states; ++d) {
      if (u(rng) >= density) continue;
      Cube c;
      for (std::uint32_t i = 0; i < atoms; ++i) {
        const double r = u(rng);
        if (r < 0.3) c.pos |= Letter{1} << i;
        else if (r < 0.6) c.neg |= Letter{1} << i;
      }
      a.add_edge(q, d, c, static_cast<Marks>(rng() & a.all_marks()));
    }
  return a;
}

// Brute force: product nodes (state, position); accepted iff some node v
// reachable from (initial, 0) reaches itself along a non-empty path that
// collects every mark (search over (node, collected marks)).
inline bool brute_accept(const Automaton& a, const LassoWord& w) {
  const std::size_t P = w.prefix.size() + w.cycle.size();
  auto letter = [&](std::size_t i) { return i < w.prefix.size() ? w.prefix[i] : w.cycle[i - w.prefix.size()]; };
  auto next = [&](std::size_t i) { return i + 1 < P ? i + 1 : w.prefix.size(); };
  using Node = std::pair<std::uint32_t, std::size_t>;
  std::set<Node> reach{{a.initial, 0}};
  std::deque<Node> todo{{a.initial, 0}};
  while (!todo.empty()) {
    auto [q, i] = todo.front();
    todo.pop_front();
    for (const Edge& e : a.edges[q])
      if (e.guard.matches(letter(i)) && reach.insert({e.dst, next(i)}).second) todo.push_back({e.dst, next(i)});
  }
  const Marks all = a.all_marks();
  for (const Node& v : reach) {
    std::set<std::pair<Node, Marks>> seen;
    std::deque<std::pair<Node, Marks>> q2;
    auto push = [&](Node n, Marks m) {
      if (seen.insert({n, m}).second) q2.push_back({n, m});
    };
    for (const Edge& e : a.edges[v.first])
      if (e.guard.matches(letter(v.second))) push({e.dst, next(v.second)}, e.marks & all);
    while (!q2.empty()) {
      auto [n, m] = q2.front();
      q2.pop_front();
      if (n == v && m == all) return true;
      for (const Edge& e : a.edges[n.first])
        if (e.guard.matches(letter(n.second))) push({e.dst, next(n.second)}, (m | e.marks) & all);
    }
  }
  return false;
}

inline LassoWord random_word(std::mt19937_64& rng, std::uint32_t atoms) {
  LassoWord w;
  const Letter mask = (Letter{1} << atoms) - 1;
  const auto np = rng() % 4, nc = 1 + rng() % 4;
  for (std::uint64_t i = 0; i < np; ++i) w.prefix.push_back(rng() & mask);
  for (std::uint64_t i = 0; i < nc; ++i) w.cycle.push_back(rng() & mask);
  return w;
}

}  // namespace rtamp::automata::test
