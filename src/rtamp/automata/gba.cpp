#include "rtamp/automata/gba.hpp"

#include <algorithm>
#include <deque>
#include <optional>
#include <unordered_map>

#include "rtamp/automata/reduce.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::automata::detail {

Automaton build_tgba(Vwaa& v) {
  if (v.num_keys > 32)
    throw Error("formula has too many distinct eventualities for a generalized Büchi automaton (at most 32)", {}, {});
  Automaton a;
  a.atoms = v.atoms;
  a.num_sets = v.num_keys;
  a.state_based = false;
  const Marks all = a.all_marks();

  std::vector<std::uint32_t> state_of;  // set id -> automaton state (UINT32_MAX = none)
  std::vector<std::uint32_t> set_of;    // automaton state -> set id (UINT32_MAX = special initial)
  std::deque<std::uint32_t> todo;
  auto lookup = [&](std::uint32_t set) {
    if (set >= state_of.size()) state_of.resize(v.sets.size(), UINT32_MAX);
    if (state_of[set] == UINT32_MAX) {
      state_of[set] = a.add_state();
      set_of.push_back(set);
      todo.push_back(state_of[set]);
    }
    return state_of[set];
  };
  std::size_t total_edges = 0;
  auto emit = [&](std::uint32_t src, const Terms& terms) {
    total_edges += terms.size();
    if (total_edges > kMaxTgbaEdges)
      throw Error("formula too large to translate: its automaton exceeds " + std::to_string(kMaxTgbaEdges) + " edges",
                  {}, {});
    for (const Term& t : terms) {
      const std::uint32_t dst = lookup(t.targets);
      a.add_edge(src, dst, t.guard, all & ~static_cast<Marks>(t.postponed));
    }
  };

  if (v.initial_sets.size() == 1) {
    a.initial = lookup(v.initial_sets[0]);
  } else {
    a.initial = a.add_state();
    set_of.push_back(UINT32_MAX);
    emit(a.initial, v.initial_delta);
  }
  Terms acc;
  while (!todo.empty()) {
    const std::uint32_t q = todo.front();
    todo.pop_front();
    acc.assign(1, Term{});
    bool dead = false;
    v.sets.for_each(set_of[q], [&](std::uint32_t s) {
      if (dead) return;
      acc = product(acc, v.delta[s], v.sets);
      if (acc.empty()) dead = true;
    });
    if (!dead) emit(q, acc);
  }
  return a;
}

}  // namespace rtamp::automata::detail

namespace rtamp::automata::detail {

namespace {

struct VecHash {
  std::size_t operator()(const std::vector<std::uint32_t>& v) const {
    std::size_t h = v.size();
    for (std::uint32_t x : v) h = h * 1000003u ^ x;
    return h;
  }
};

}  // namespace

std::optional<Automaton> build_tgba_merged(Vwaa& v, std::size_t max_states) {
  if (v.num_keys > 32)
    throw Error("formula has too many distinct eventualities for a generalized Büchi automaton (at most 32)", {}, {});
  if (v.atoms.size() > kMaxMergedAtoms) return build_tgba(v);
  Automaton a;
  a.atoms = v.atoms;
  a.num_sets = v.num_keys;
  a.state_based = false;
  const Marks all = a.all_marks();
  const std::uint32_t n_letters = 1u << v.atoms.size();

  // GO terms of a conjunction, cached per set id.
  std::unordered_map<std::uint32_t, Terms> conj_terms;
  auto terms_of = [&](std::uint32_t set) -> const Terms& {
    auto it = conj_terms.find(set);
    if (it != conj_terms.end()) return it->second;
    Terms acc{Term{}};
    v.sets.for_each(set, [&](std::uint32_t s) {
      if (!acc.empty()) acc = product(acc, v.delta[s], v.sets);
    });
    return conj_terms.emplace(set, std::move(acc)).first->second;
  };
  // Antichain of conjunctions (a disjunction): drop supersets, sort.
  auto minimise = [&](std::vector<std::uint32_t>& d) {
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
    std::size_t w = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      bool redundant = false;
      for (std::size_t j = 0; j < d.size() && !redundant; ++j)
        if (j != i && v.sets.subset(d[j], d[i])) redundant = true;
      if (!redundant) d[w++] = d[i];
    }
    d.resize(w);
  };
  std::unordered_map<std::vector<std::uint32_t>, std::uint32_t, VecHash> ids;
  std::vector<std::vector<std::uint32_t>> disj;
  bool over_budget = false;
  auto lookup = [&](std::vector<std::uint32_t> d) {
    auto [it, fresh] = ids.emplace(std::move(d), 0);
    if (fresh) {
      it->second = a.add_state();
      disj.push_back(it->first);
      if (a.num_states() > max_states) over_budget = true;
    }
    return it->second;
  };
  std::vector<std::uint32_t> init = v.initial_sets;
  minimise(init);
  if (init.empty()) {
    a.initial = a.add_state();
    return a;
  }
  a.initial = lookup(init);

  std::vector<const Term*> applicable;
  std::vector<std::uint32_t> dest;
  // (destination state, marks) -> letters, for one source state.
  std::unordered_map<std::uint64_t, std::vector<Letter>> out;
  std::size_t total_edges = 0;
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    if (over_budget) return std::nullopt;
    std::vector<const Term*> terms;
    const std::vector<std::uint32_t> members = disj[q];  // copy: lookup() may grow disj
    for (std::uint32_t set : members)
      for (const Term& t : terms_of(set)) terms.push_back(&t);
    out.clear();
    for (Letter sigma = 0; sigma < n_letters; ++sigma) {
      applicable.clear();
      std::uint64_t keys = 0;
      for (const Term* t : terms)
        if (t->guard.matches(sigma)) {
          applicable.push_back(t);
          keys |= t->postponed;
        }
      if (applicable.empty()) continue;
      // Every promise assignment pi ⊆ keys (submasks, smallest first by
      // enumeration from 0 upwards in the lattice of submasks).
      std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>> seen;  // pi, dest
      for (std::uint64_t pi = 0;; pi = (pi - keys) & keys) {
        dest.clear();
        for (const Term* t : applicable)
          if ((t->postponed & ~pi) == 0) dest.push_back(t->targets);
        if (!dest.empty()) {
          minimise(dest);
          // A larger pi with the same destination only has fewer marks.
          bool dominated = false;
          for (const auto& [pj, dj] : seen)
            if ((pj & ~pi) == 0 && dj == dest) { dominated = true; break; }
          if (!dominated) {
            seen.emplace_back(pi, dest);
            const std::uint32_t d = lookup(dest);
            const Marks m = all & ~static_cast<Marks>(pi);
            out[(std::uint64_t{d} << 32) | m].push_back(sigma);
          }
        }
        if (pi == keys) break;
      }
    }
    const Letter full = n_letters - 1;
    for (auto& [key, letters] : out) {
      total_edges += letters.size();
      if (total_edges > kMaxTgbaEdges)
        throw Error("formula too large to translate: its automaton exceeds " + std::to_string(kMaxTgbaEdges) +
                        " edges",
                    {}, {});
      for (Letter l : letters)
        a.edges[q].push_back(Edge{static_cast<std::uint32_t>(key >> 32), Cube{l, full & ~l},
                                  static_cast<Marks>(key & 0xffffffffu)});
    }
  }
  merge_parallel_edges(a);
  return a;
}

}  // namespace rtamp::automata::detail
