#include "rtamp/automata/wdba.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <vector>

#include "rtamp/automata/lasso_accept.hpp"
#include "rtamp/automata/reduce.hpp"

namespace rtamp::automata {

namespace {

constexpr unsigned kMaxLetterBits = 12;
constexpr std::size_t kMaxTableWords = std::size_t{1} << 22;  // successor table: 32 MiB
constexpr std::size_t kMaxSubsetCells = std::size_t{1} << 22;  // subsets × letters

// A complete deterministic automaton over the 2^k letters of the used atoms.
struct Table {
  std::vector<std::uint32_t> used;  // atom indices; letter bit j is atom used[j]
  std::uint32_t letters = 1;
  std::vector<std::vector<std::uint32_t>> next;  // [state][letter]
  std::vector<bool> accepting;
  std::uint32_t initial = 0;

  Letter expand(std::uint32_t l) const {
    Letter r = 0;
    for (std::size_t j = 0; j < used.size(); ++j)
      if ((l >> j) & 1u) r |= Letter{1} << used[j];
    return r;
  }
  Cube minterm(std::uint32_t l) const {
    Letter mask = 0;
    for (std::uint32_t u : used) mask |= Letter{1} << u;
    const Letter pos = expand(l);
    return {pos, mask & ~pos};
  }
};

// Subsets are bitsets of `words` 64-bit words; succ[q][l] is the set of
// successors of q on letter l.
std::optional<Table> subset_construction(const Automaton& a, std::size_t max_states) {
  Table t;
  Letter mentioned = 0;
  for (const auto& out : a.edges)
    for (const Edge& e : out) mentioned |= e.guard.pos | e.guard.neg;
  for (std::uint32_t i = 0; i < kMaxAtoms; ++i)
    if ((mentioned >> i) & 1u) t.used.push_back(i);
  if (t.used.size() > kMaxLetterBits) return std::nullopt;
  t.letters = std::uint32_t{1} << t.used.size();
  const std::size_t n = a.num_states(), words = (n + 63) / 64;
  if (n * t.letters * words > kMaxTableWords) return std::nullopt;
  using Set = std::vector<std::uint64_t>;
  std::vector<std::uint64_t> succ(n * t.letters * words, 0);  // [q][l][word]
  for (std::uint32_t l = 0; l < t.letters; ++l) {
    const Letter letter = t.expand(l);
    for (std::size_t q = 0; q < n; ++q)
      for (const Edge& e : a.edges[q])
        if (e.guard.matches(letter)) succ[(q * t.letters + l) * words + e.dst / 64] |= std::uint64_t{1} << (e.dst % 64);
  }
  std::map<Set, std::uint32_t> id;
  std::vector<Set> sets;
  auto intern = [&](Set s) {
    auto [it, fresh] = id.emplace(s, static_cast<std::uint32_t>(sets.size()));
    if (fresh) sets.push_back(std::move(s));
    return it->second;
  };
  Set init(words, 0);
  init[a.initial / 64] |= std::uint64_t{1} << (a.initial % 64);
  t.initial = intern(std::move(init));
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets.size() > max_states || sets.size() * t.letters > kMaxSubsetCells) return std::nullopt;
    std::vector<std::uint32_t> row(t.letters);
    for (std::uint32_t l = 0; l < t.letters; ++l) {
      Set dst(words, 0);
      for (std::size_t w = 0; w < words; ++w)
        for (std::uint64_t bits = sets[i][w]; bits; bits &= bits - 1) {
          const std::size_t q = w * 64 + static_cast<std::size_t>(__builtin_ctzll(bits));
          const std::uint64_t* from = &succ[(q * t.letters + l) * words];
          for (std::size_t x = 0; x < words; ++x) dst[x] |= from[x];
        }
      row[l] = intern(std::move(dst));
    }
    t.next.push_back(std::move(row));
  }
  if (sets.size() > max_states) return std::nullopt;
  return t;
}

// One edge per (state, successor): the structure SCCs and paths need, with a
// letter that takes it (guard.pos of a minterm).
Automaton skeleton(const Table& t) {
  Automaton s;
  for (std::size_t q = 0; q < t.next.size(); ++q) s.add_state();
  for (std::uint32_t q = 0; q < t.next.size(); ++q) {
    std::vector<bool> seen(t.next.size(), false);
    for (std::uint32_t l = 0; l < t.letters; ++l) {
      const std::uint32_t d = t.next[q][l];
      if (seen[d]) continue;
      seen[d] = true;
      s.add_edge(q, d, t.minterm(l));
    }
  }
  s.initial = t.initial;
  return s;
}

// Letters of a shortest path from `from` to `to` (to == from: a non-empty
// cycle) using only states `ok` admits.
template <class Ok>
std::vector<Letter> path(const Automaton& s, std::uint32_t from, std::uint32_t to, Ok&& ok) {
  std::vector<std::pair<std::uint32_t, Letter>> parent(s.num_states(), {UINT32_MAX, 0});
  std::vector<bool> seen(s.num_states(), false);
  std::deque<std::uint32_t> todo;
  for (const Edge& e : s.edges[from])
    if (ok(e.dst) && !seen[e.dst]) {
      seen[e.dst] = true;
      parent[e.dst] = {from, e.guard.pos};
      todo.push_back(e.dst);
    }
  if (from == to && seen[to]) return {parent[to].second};
  while (!todo.empty() && !seen[to]) {
    const std::uint32_t q = todo.front();
    todo.pop_front();
    for (const Edge& e : s.edges[q])
      if (ok(e.dst) && !seen[e.dst]) {
        seen[e.dst] = true;
        parent[e.dst] = {q, e.guard.pos};
        todo.push_back(e.dst);
      }
  }
  std::vector<Letter> letters;
  std::uint32_t q = to;
  do {
    letters.push_back(parent[q].second);
    q = parent[q].first;
  } while (q != from);
  std::reverse(letters.begin(), letters.end());
  return letters;
}

// Accepting states of t, for each status (rejecting, accepting) given to a
// state on no cycle whose successors disagree.
std::array<std::vector<bool>, 2> mark_accepting(const Automaton& a, const Table& t) {
  const Automaton s = skeleton(t);
  const SccInfo info = scc_decompose(s);
  std::vector<std::uint32_t> rep(info.count, UINT32_MAX);
  for (std::uint32_t q = 0; q < s.num_states(); ++q)
    if (rep[info.scc_of[q]] == UINT32_MAX) rep[info.scc_of[q]] = q;
  std::vector<int> status(info.count, -1);  // 1 accepting, 0 rejecting, -1 transient
  for (std::uint32_t c = 0; c < info.count; ++c) {
    if (!info.has_cycle[c]) continue;
    const std::uint32_t r = rep[c];
    LassoWord w;
    if (r != s.initial) w.prefix = path(s, s.initial, r, [](std::uint32_t) { return true; });
    w.cycle = path(s, r, r, [&](std::uint32_t q) { return info.scc_of[q] == c; });
    status[c] = lasso_accept(a, w) ? 1 : 0;
  }
  // SCCs are numbered so that edges go to lower numbers: successors first.
  std::array<std::vector<bool>, 2> result;
  for (int mixed = 0; mixed < 2; ++mixed) {
    std::vector<int> st = status;
    for (std::uint32_t c = 0; c < info.count; ++c) {
      if (st[c] != -1) continue;
      int shared = -2;
      for (const Edge& e : s.edges[rep[c]]) {
        const int d = st[info.scc_of[e.dst]];
        shared = (shared == -2 || shared == d) ? d : -1;
      }
      st[c] = shared < 0 ? mixed : shared;
    }
    result[mixed].assign(t.next.size(), false);
    for (std::uint32_t q = 0; q < t.next.size(); ++q) result[mixed][q] = st[info.scc_of[q]] == 1;
  }
  return result;
}

// Moore's partition refinement; returns the class of every state, classes
// numbered by first occurrence in BFS order from the initial state.
std::vector<std::uint32_t> moore(const Table& t, std::uint32_t& classes) {
  const std::size_t n = t.next.size();
  std::vector<std::uint32_t> cls(n);
  for (std::size_t q = 0; q < n; ++q) cls[q] = t.accepting[q] ? 1 : 0;
  std::uint32_t count = 0;
  for (;;) {
    std::map<std::vector<std::uint32_t>, std::uint32_t> sig;
    std::vector<std::uint32_t> next(n);
    for (std::size_t q = 0; q < n; ++q) {
      std::vector<std::uint32_t> key{cls[q]};
      for (std::uint32_t d : t.next[q]) key.push_back(cls[d]);
      next[q] = sig.emplace(std::move(key), static_cast<std::uint32_t>(sig.size())).first->second;
    }
    const auto fresh = static_cast<std::uint32_t>(sig.size());
    cls = std::move(next);
    if (fresh == count) break;
    count = fresh;
  }
  classes = count;
  return cls;
}

// Cubes covering exactly the letters l (within the subcube fixed by
// `mask`/`value` over letter bits >= bit) for which in(l) holds.
template <class In>
void cover(const Table& t, In&& in, std::uint32_t bit, std::uint32_t mask, std::uint32_t value, std::vector<Cube>& out) {
  bool any = false, all = true;
  for (std::uint32_t l = 0; l < t.letters; ++l) {
    if ((l & mask) != value) continue;
    if (in(l))
      any = true;
    else
      all = false;
  }
  if (!any) return;
  if (all) {
    Cube c;
    for (std::size_t j = 0; j < t.used.size(); ++j) {
      if (!((mask >> j) & 1u)) continue;
      const Letter atom = Letter{1} << t.used[j];
      ((value >> j) & 1u ? c.pos : c.neg) |= atom;
    }
    out.push_back(c);
    return;
  }
  const std::uint32_t b = std::uint32_t{1} << bit;
  cover(t, in, bit + 1, mask | b, value, out);
  cover(t, in, bit + 1, mask | b, value | b, out);
}

}  // namespace

std::optional<Automaton> minimize_wdba(const Automaton& a, std::size_t max_states) {
  std::optional<Table> t = subset_construction(a, max_states);
  if (!t) return std::nullopt;
  // Either status for the mixed transient states keeps the language; keep
  // the one that merges more.
  std::array<std::vector<bool>, 2> accepting = mark_accepting(a, *t);
  std::uint32_t classes = 0;
  t->accepting = std::move(accepting[0]);
  std::vector<std::uint32_t> cls = moore(*t, classes);
  std::vector<bool> first = std::move(t->accepting);
  t->accepting = std::move(accepting[1]);
  std::uint32_t alt_classes = 0;
  std::vector<std::uint32_t> alt_cls = moore(*t, alt_classes);
  if (alt_classes < classes) {
    cls = std::move(alt_cls);
    classes = alt_classes;
  } else {
    t->accepting = std::move(first);
  }
  // Renumber classes in BFS order from the initial state's class.
  std::vector<std::uint32_t> rep(classes, UINT32_MAX);
  for (std::uint32_t q = 0; q < t->next.size(); ++q)
    if (rep[cls[q]] == UINT32_MAX) rep[cls[q]] = q;
  std::vector<std::uint32_t> order(classes, UINT32_MAX);
  std::vector<std::uint32_t> bfs{cls[t->initial]};
  order[cls[t->initial]] = 0;
  for (std::size_t i = 0; i < bfs.size(); ++i)
    for (std::uint32_t d : t->next[rep[bfs[i]]])
      if (order[cls[d]] == UINT32_MAX) {
        order[cls[d]] = static_cast<std::uint32_t>(bfs.size());
        bfs.push_back(cls[d]);
      }
  Automaton w;
  w.atoms = a.atoms;
  w.state_based = true;
  w.num_sets = 1;
  w.name = a.name;
  for (std::uint32_t c : bfs) w.add_state(t->accepting[rep[c]]);
  for (std::uint32_t i = 0; i < bfs.size(); ++i) {
    const std::uint32_t q = rep[bfs[i]];
    std::vector<bool> done(bfs.size(), false);
    for (std::uint32_t l = 0; l < t->letters; ++l) {
      const std::uint32_t d = order[cls[t->next[q][l]]];
      if (done[d]) continue;
      done[d] = true;
      std::vector<Cube> cubes;
      const auto goes = [&](std::uint32_t x) { return order[cls[t->next[q][x]]] == d; };
      cover(*t, goes, 0, 0, 0, cubes);
      for (const Cube& c : cubes) w.add_edge(i, d, c);
    }
  }
  merge_parallel_edges(w);
  return w;
}

}  // namespace rtamp::automata
