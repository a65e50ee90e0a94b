#include "rtamp/automata/reduce.hpp"

#include <algorithm>
#include <deque>
#include <tuple>

namespace rtamp::automata {

namespace {

// Tarjan over the edges accepted by `keep(src, edge)`.
template <class Keep>
std::vector<std::uint32_t> tarjan(const Automaton& a, Keep&& keep, std::uint32_t& count) {
  const std::uint32_t n = a.num_states();
  constexpr std::uint32_t kNone = UINT32_MAX;
  std::vector<std::uint32_t> index(n, kNone), low(n, 0), scc(n, kNone);
  std::vector<std::uint32_t> stack;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> call;  // (state, next edge)
  std::uint32_t next_index = 0;
  count = 0;
  for (std::uint32_t root = 0; root < n; ++root) {
    if (index[root] != kNone) continue;
    call.emplace_back(root, 0);
    index[root] = low[root] = next_index++;
    stack.push_back(root);
    while (!call.empty()) {
      auto& [q, e] = call.back();
      const auto& out = a.edges[q];
      if (e < out.size()) {
        const Edge& ed = out[e++];
        if (!keep(q, ed)) continue;
        const std::uint32_t d = ed.dst;
        if (index[d] == kNone) {
          index[d] = low[d] = next_index++;
          stack.push_back(d);
          call.emplace_back(d, 0);
        } else if (scc[d] == kNone) {
          low[q] = std::min(low[q], index[d]);
        }
        continue;
      }
      const std::uint32_t qq = q;
      call.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[qq]);
      if (low[qq] == index[qq]) {
        std::uint32_t s;
        do {
          s = stack.back();
          stack.pop_back();
          scc[s] = count;
        } while (s != qq);
        ++count;
      }
    }
  }
  return scc;
}

}  // namespace

SccInfo scc_decompose(const Automaton& a) {
  SccInfo info;
  info.scc_of = tarjan(a, [](std::uint32_t, const Edge&) { return true; }, info.count);
  info.internal_marks.assign(info.count, 0);
  info.has_cycle.assign(info.count, false);
  for (std::uint32_t q = 0; q < a.num_states(); ++q)
    for (const Edge& e : a.edges[q])
      if (info.scc_of[e.dst] == info.scc_of[q]) {
        info.has_cycle[info.scc_of[q]] = true;
        info.internal_marks[info.scc_of[q]] |= e.marks;
      }
  return info;
}

void remove_useless(Automaton& a) {
  const std::uint32_t n = a.num_states();
  const Marks all = a.all_marks();
  // Reachable states.
  std::vector<bool> reach(n, false);
  std::vector<std::uint32_t> order;
  std::deque<std::uint32_t> todo{a.initial};
  reach[a.initial] = true;
  while (!todo.empty()) {
    std::uint32_t q = todo.front();
    todo.pop_front();
    for (const Edge& e : a.edges[q])
      if (!reach[e.dst]) { reach[e.dst] = true; todo.push_back(e.dst); }
  }
  const SccInfo info = scc_decompose(a);
  // Useful SCCs: accepting, or with an edge to a useful SCC. SCC numbers are
  // in reverse topological order, so process them in increasing order.
  std::vector<std::vector<std::uint32_t>> members(info.count);
  for (std::uint32_t q = 0; q < n; ++q) members[info.scc_of[q]].push_back(q);
  std::vector<bool> useful(info.count, false);
  for (std::uint32_t s = 0; s < info.count; ++s) {
    bool u = info.accepting(s, all);
    for (std::uint32_t q : members[s]) {
      if (u) break;
      for (const Edge& e : a.edges[q])
        if (info.scc_of[e.dst] != s && useful[info.scc_of[e.dst]]) { u = true; break; }
    }
    useful[s] = u;
  }
  auto keep = [&](std::uint32_t q) { return reach[q] && useful[info.scc_of[q]]; };
  Automaton out;
  out.atoms = a.atoms;
  out.num_sets = a.num_sets;
  out.state_based = a.state_based;
  out.name = a.name;
  if (!keep(a.initial)) {
    out.initial = out.add_state(false);
    a = std::move(out);
    return;
  }
  std::vector<std::uint32_t> renum(n, UINT32_MAX);
  renum[a.initial] = out.add_state(a.state_accepting[a.initial]);
  order.push_back(a.initial);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t q = order[i];
    for (const Edge& e : a.edges[q])
      if (keep(e.dst) && renum[e.dst] == UINT32_MAX) {
        renum[e.dst] = out.add_state(a.state_accepting[e.dst]);
        order.push_back(e.dst);
      }
  }
  for (std::uint32_t q : order)
    for (const Edge& e : a.edges[q])
      if (renum[e.dst] != UINT32_MAX) out.edges[renum[q]].push_back(Edge{renum[e.dst], e.guard, e.marks});
  out.initial = 0;
  a = std::move(out);
}

void canonicalize_acceptance(Automaton& a, bool saturate) {
  const std::uint32_t n = a.num_states();
  const SccInfo info = scc_decompose(a);
  const Marks all = a.all_marks();
  auto internal_acc = [&](std::uint32_t q, const Edge& e) {
    return info.scc_of[q] == info.scc_of[e.dst] && info.accepting(info.scc_of[q], all);
  };
  // 1. Marks only matter on edges inside accepting SCCs.
  for (std::uint32_t q = 0; q < n; ++q) {
    if (a.state_based) {
      if (!info.accepting(info.scc_of[q], all)) a.state_accepting[q] = false;
      for (Edge& e : a.edges[q]) e.marks = a.state_accepting[q] ? 1u : 0u;
    } else {
      for (Edge& e : a.edges[q])
        if (!internal_acc(q, e)) e.marks = 0;
    }
  }
  // 2. Saturation: an internal edge that lies on no cycle avoiding set i can
  //    carry i (every closed walk through it visits i anyway). For a
  //    state-based automaton: a state on no cycle of non-accepting states can
  //    be accepting.
  for (std::uint32_t i = 0; i < (saturate ? a.num_sets : 0u); ++i) {
    const Marks bit = Marks{1} << i;
    std::uint32_t cnt = 0;
    const auto sub = tarjan(
        a, [&](std::uint32_t q, const Edge& e) { return internal_acc(q, e) && !(e.marks & bit); }, cnt);
    for (std::uint32_t q = 0; q < n; ++q) {
      if (a.state_based) {
        if (a.state_accepting[q] || !info.accepting(info.scc_of[q], all)) continue;
        bool on_cycle = false;
        for (const Edge& e : a.edges[q])
          if (internal_acc(q, e) && sub[q] == sub[e.dst]) on_cycle = true;
        if (!on_cycle) {
          a.state_accepting[q] = true;
          for (Edge& e : a.edges[q]) e.marks = 1u;
        }
      } else {
        for (Edge& e : a.edges[q])
          if (internal_acc(q, e) && !(e.marks & bit) && sub[q] != sub[e.dst]) e.marks |= bit;
      }
    }
  }
  if (a.state_based || a.num_sets == 0) return;
  // 3. A set that every edge of another set also carries is redundant.
  std::vector<Marks> implied(a.num_sets, all);  // implied[j]: sets present on every internal edge with j
  bool non_accepting_cycle = false;
  for (std::uint32_t q = 0; q < n; ++q)
    for (const Edge& e : a.edges[q]) {
      if (info.scc_of[q] != info.scc_of[e.dst]) continue;
      if (!internal_acc(q, e)) { non_accepting_cycle = true; continue; }
      for (std::uint32_t j = 0; j < a.num_sets; ++j)
        if ((e.marks >> j) & 1u) implied[j] &= e.marks;
    }
  Marks keep = all;
  for (std::uint32_t i = 0; i < a.num_sets; ++i)
    for (std::uint32_t j = 0; j < a.num_sets; ++j)
      if (j != i && ((keep >> j) & 1u) && ((implied[j] >> i) & 1u)) {
        keep &= ~(Marks{1} << i);
        break;
      }
  // Every accepting cycle sees every remaining set on every edge: no set needed.
  bool saturated = !non_accepting_cycle;
  for (std::uint32_t q = 0; q < n && saturated; ++q)
    for (const Edge& e : a.edges[q])
      if (info.scc_of[q] == info.scc_of[e.dst] && (e.marks & keep) != keep) { saturated = false; break; }
  if (saturated) keep = 0;
  if (keep == all) return;
  std::uint32_t k = 0;
  std::vector<std::uint32_t> to(a.num_sets, 0);
  for (std::uint32_t i = 0; i < a.num_sets; ++i)
    if ((keep >> i) & 1u) to[i] = k++;
  for (auto& out : a.edges)
    for (Edge& e : out) {
      Marks m = 0;
      for (std::uint32_t i = 0; i < a.num_sets; ++i)
        if (((keep & e.marks) >> i) & 1u) m |= Marks{1} << to[i];
      e.marks = m;
    }
  a.num_sets = k;
}

void merge_parallel_edges(Automaton& a) {
  for (auto& out : a.edges) {
    std::sort(out.begin(), out.end(), [](const Edge& x, const Edge& y) {
      return std::tie(x.dst, x.marks, x.guard.pos, x.guard.neg) < std::tie(y.dst, y.marks, y.guard.pos, y.guard.neg);
    });
    out.erase(std::unique(out.begin(), out.end()), out.end());
    std::vector<Edge> result;
    for (std::size_t b = 0; b < out.size();) {
      std::size_t e = b;
      while (e < out.size() && out[e].dst == out[b].dst && out[e].marks == out[b].marks) ++e;
      std::vector<Cube> cubes;
      for (std::size_t i = b; i < e; ++i) cubes.push_back(out[i].guard);
      bool changed = true;
      while (changed && cubes.size() > 1) {
        changed = false;
        // Drop implied cubes.
        for (std::size_t i = 0; i < cubes.size() && !changed; ++i)
          for (std::size_t j = 0; j < cubes.size(); ++j)
            if (i != j && cubes[i].implies(cubes[j])) {
              cubes.erase(cubes.begin() + static_cast<std::ptrdiff_t>(i));
              changed = true;
              break;
            }
        if (changed) continue;
        // Merge c∧v, c∧!v.
        for (std::size_t i = 0; i < cubes.size() && !changed; ++i)
          for (std::size_t j = i + 1; j < cubes.size(); ++j) {
            const Cube& x = cubes[i];
            const Cube& y = cubes[j];
            const Letter vx = x.pos & y.neg, vy = x.neg & y.pos;
            const Letter v = vx | vy;
            if (v && (v & (v - 1)) == 0 && (x.pos & ~v) == (y.pos & ~v) && (x.neg & ~v) == (y.neg & ~v)) {
              cubes[i] = Cube{x.pos & ~v, x.neg & ~v};
              cubes.erase(cubes.begin() + static_cast<std::ptrdiff_t>(j));
              changed = true;
              break;
            }
          }
        // Merge c∧v with c' where c' ⊇ ... : x = c∧v and y implies c∧!v's
        // complement is not needed; the two rules above reach the common cases.
      }
      for (const Cube& c : cubes) result.push_back(Edge{out[b].dst, c, out[b].marks});
      b = e;
    }
    out = std::move(result);
  }
}

namespace {
bool covered_rec(const Cube& g, std::vector<Cube>& scratch, std::size_t base) {
  // Candidates live in scratch[base..].
  const std::size_t begin = scratch.size();
  for (std::size_t i = base; i < begin; ++i) {
    const Cube h = scratch[i];
    if ((g & h).is_false()) continue;
    if (g.implies(h)) {
      scratch.resize(begin);
      return true;
    }
    scratch.push_back(h);
  }
  const std::size_t end = scratch.size();
  if (end == begin) return false;
  const Cube& first = scratch[begin];
  const Letter free = (first.pos | first.neg) & ~(g.pos | g.neg);
  const Letter v = free & (~free + 1);
  bool ok = covered_rec(Cube{g.pos | v, g.neg}, scratch, begin) &&
            covered_rec(Cube{g.pos, g.neg | v}, scratch, begin);
  scratch.resize(begin);
  return ok;
}
}  // namespace

bool cube_covered(const Cube& g, const std::vector<Cube>& hs) {
  if (g.is_false()) return true;
  std::vector<Cube> scratch(hs.begin(), hs.end());
  return covered_rec(g, scratch, 0);
}

}  // namespace rtamp::automata
