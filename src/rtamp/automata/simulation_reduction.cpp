#include "rtamp/automata/simulation_reduction.hpp"

#include <algorithm>

#include "rtamp/automata/reduce.hpp"

namespace rtamp::automata {

namespace {

class Relation {
 public:
  explicit Relation(std::uint32_t n) : words_((n + 63) / 64), bits_(std::size_t{n} * words_, ~std::uint64_t{0}) {}
  bool get(std::uint32_t q, std::uint32_t r) const { return (bits_[q * words_ + r / 64] >> (r % 64)) & 1u; }
  void clear(std::uint32_t q, std::uint32_t r) { bits_[q * words_ + r / 64] &= ~(std::uint64_t{1} << (r % 64)); }

 private:
  std::size_t words_;
  std::vector<std::uint64_t> bits_;
};

// Greatest direct simulation: sim.get(q, r) iff r simulates q. With
// `pinned` < n, the pinned state can only be simulated by itself (used for
// cosimulation, where it is the initial state).
Relation compute_simulation(const Automaton& a, std::uint32_t pinned = UINT32_MAX,
                            const std::vector<bool>* accepting = nullptr) {
  const std::uint32_t n = a.num_states();
  Relation sim(n);
  if (accepting)
    for (std::uint32_t q = 0; q < n; ++q)
      for (std::uint32_t r = 0; r < n; ++r)
        if ((*accepting)[q] && !(*accepting)[r]) sim.clear(q, r);
  if (pinned < n)
    for (std::uint32_t r = 0; r < n; ++r)
      if (r != pinned) sim.clear(pinned, r);
  std::vector<Cube> hs;
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::uint32_t q = 0; q < n; ++q)
      for (std::uint32_t r = 0; r < n; ++r) {
        if (q == r || !sim.get(q, r)) continue;
        for (const Edge& e : a.edges[q]) {
          hs.clear();
          bool direct = false;
          for (const Edge& f : a.edges[r]) {
            if ((e.marks & ~f.marks) != 0 || !sim.get(e.dst, f.dst)) continue;
            if ((e.guard & f.guard).is_false()) continue;
            if (e.guard.implies(f.guard)) { direct = true; break; }
            hs.push_back(f.guard);
          }
          if (!direct && !cube_covered(e.guard, hs)) {
            sim.clear(q, r);
            changed = true;
            break;
          }
        }
      }
  }
  return sim;
}

}  // namespace

std::vector<std::vector<bool>> direct_simulation(const Automaton& a) {
  const std::uint32_t n = a.num_states();
  const Relation sim = compute_simulation(a);
  std::vector<std::vector<bool>> out(n, std::vector<bool>(n));
  for (std::uint32_t q = 0; q < n; ++q)
    for (std::uint32_t r = 0; r < n; ++r) out[q][r] = sim.get(q, r);
  return out;
}

bool reduce_cosimulation(Automaton& a) {
  const std::uint32_t n = a.num_states();
  if (n < 2 || n > kMaxSimulationStates || std::uint64_t{n} * a.num_edges() > kMaxSimulationWork) return false;
  Automaton rev;
  rev.num_sets = a.num_sets;
  rev.edges.resize(n);
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : a.edges[q]) rev.edges[e.dst].push_back(Edge{q, e.guard, e.marks});
  // State-based: the marks of a state sit on its out-edges, so compare the
  // states' own acceptance (acc(q) => acc(r)) as backward simulation requires.
  const Relation sim = compute_simulation(rev, a.initial, a.state_based ? &a.state_accepting : nullptr);
  std::vector<std::uint32_t> cls(n, UINT32_MAX), rep;
  for (std::uint32_t q = 0; q < n; ++q) {
    if (cls[q] != UINT32_MAX) continue;
    cls[q] = static_cast<std::uint32_t>(rep.size());
    for (std::uint32_t r = q + 1; r < n; ++r)
      if (cls[r] == UINT32_MAX && sim.get(q, r) && sim.get(r, q)) cls[r] = cls[q];
    rep.push_back(q);
  }
  const auto m = static_cast<std::uint32_t>(rep.size());
  if (m == n) return false;
  Automaton out;
  out.atoms = a.atoms;
  out.num_sets = a.num_sets;
  out.state_based = a.state_based;
  out.name = a.name;
  for (std::uint32_t c = 0; c < m; ++c) out.add_state(a.state_accepting[rep[c]]);
  out.initial = cls[a.initial];
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : a.edges[q]) out.edges[cls[q]].push_back(Edge{cls[e.dst], e.guard, e.marks});
  merge_parallel_edges(out);
  a = std::move(out);
  return true;
}

bool reduce_direct_simulation(Automaton& a) {
  const std::uint32_t n = a.num_states();
  if (n < 2 || n > kMaxSimulationStates || std::uint64_t{n} * a.num_edges() > kMaxSimulationWork) return false;
  for (const auto& out : a.edges)
    if (out.empty()) return false;  // precondition: no useless states
  const Relation sim = compute_simulation(a);

  // Classes of mutual simulation, numbered by first member.
  std::vector<std::uint32_t> cls(n, UINT32_MAX), rep;
  for (std::uint32_t q = 0; q < n; ++q) {
    if (cls[q] != UINT32_MAX) continue;
    cls[q] = static_cast<std::uint32_t>(rep.size());
    for (std::uint32_t r = q + 1; r < n; ++r)
      if (cls[r] == UINT32_MAX && sim.get(q, r) && sim.get(r, q)) cls[r] = cls[q];
    rep.push_back(q);
  }
  const auto m = static_cast<std::uint32_t>(rep.size());

  Automaton out;
  out.atoms = a.atoms;
  out.num_sets = a.num_sets;
  out.state_based = a.state_based;
  out.name = a.name;
  for (std::uint32_t c = 0; c < m; ++c) out.add_state(a.state_accepting[rep[c]]);
  out.initial = cls[a.initial];
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : a.edges[q]) out.edges[cls[q]].push_back(Edge{cls[e.dst], e.guard, e.marks});
  merge_parallel_edges(out);

  // Little-brother pruning on the quotient (relation between classes via representatives).
  std::size_t removed = 0;
  std::vector<Cube> hs;
  for (std::uint32_t c = 0; c < m; ++c) {
    auto& edges = out.edges[c];
    std::vector<char> drop(edges.size(), 0);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const Edge& e = edges[i];
      hs.clear();
      for (std::size_t j = 0; j < edges.size(); ++j) {
        const Edge& f = edges[j];
        if (i == j || (f.dst == e.dst && f.marks == e.marks)) continue;
        if ((e.marks & ~f.marks) != 0 || !sim.get(rep[e.dst], rep[f.dst])) continue;
        if ((e.guard & f.guard).is_false()) continue;
        hs.push_back(f.guard);
      }
      if (!hs.empty() && cube_covered(e.guard, hs)) drop[i] = 1;
    }
    std::size_t w = 0;
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (!drop[i]) edges[w++] = edges[i];
    removed += edges.size() - w;
    edges.resize(w);
  }
  const bool changed = m < n || removed > 0;
  a = std::move(out);
  if (removed > 0) remove_useless(a);  // pruning may disconnect states
  return changed;
}

}  // namespace rtamp::automata
