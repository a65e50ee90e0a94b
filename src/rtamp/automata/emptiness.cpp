#include "rtamp/automata/emptiness.hpp"

#include <algorithm>
#include <deque>

#include "rtamp/automata/reduce.hpp"

namespace rtamp::automata {

namespace {

struct Step {
  std::uint32_t from = UINT32_MAX;
  const Edge* edge = nullptr;
};

// BFS from `src` over edges allowed by `ok`, until `goal(state, edge)` holds
// for an edge; returns the letters of the path including that edge, and the
// state reached. Empty optional if unreachable.
template <class Ok, class Goal>
std::optional<std::pair<std::vector<Letter>, std::uint32_t>> bfs(const Automaton& a, std::uint32_t src, Ok&& ok,
                                                                  Goal&& goal) {
  std::vector<Step> parent(a.num_states());
  std::vector<bool> seen(a.num_states(), false);
  std::deque<std::uint32_t> todo{src};
  seen[src] = true;
  auto path_to = [&](std::uint32_t q) {
    std::vector<Letter> letters;
    while (q != src) {
      letters.push_back(parent[q].edge->guard.pos);
      q = parent[q].from;
    }
    std::reverse(letters.begin(), letters.end());
    return letters;
  };
  while (!todo.empty()) {
    const std::uint32_t q = todo.front();
    todo.pop_front();
    for (const Edge& e : a.edges[q]) {
      if (!ok(q, e)) continue;
      if (goal(q, e)) {
        std::vector<Letter> letters = path_to(q);
        letters.push_back(e.guard.pos);
        return std::make_pair(std::move(letters), e.dst);
      }
      if (!seen[e.dst]) {
        seen[e.dst] = true;
        parent[e.dst] = {q, &e};
        todo.push_back(e.dst);
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<LassoWord> find_accepting_lasso(const Automaton& a) {
  if (a.num_states() == 0) return std::nullopt;
  const Marks all = a.all_marks();
  const SccInfo info = scc_decompose(a);
  // Reachable states, BFS order.
  std::vector<bool> reach(a.num_states(), false);
  std::deque<std::uint32_t> todo{a.initial};
  reach[a.initial] = true;
  std::uint32_t target = UINT32_MAX;
  while (!todo.empty() && target == UINT32_MAX) {
    const std::uint32_t q = todo.front();
    todo.pop_front();
    if (info.accepting(info.scc_of[q], all)) { target = q; break; }
    for (const Edge& e : a.edges[q])
      if (!reach[e.dst]) { reach[e.dst] = true; todo.push_back(e.dst); }
  }
  if (target == UINT32_MAX) return std::nullopt;
  LassoWord w;
  if (target != a.initial) {
    auto p = bfs(a, a.initial, [](std::uint32_t, const Edge&) { return true; },
                 [&](std::uint32_t, const Edge& e) { return e.dst == target; });
    w.prefix = std::move(p->first);
  }
  const std::uint32_t scc = info.scc_of[target];
  auto inside = [&](std::uint32_t, const Edge& e) { return info.scc_of[e.dst] == scc; };
  std::uint32_t cur = target;
  Marks need = all;
  while (need) {
    const Marks bit = need & (~need + 1);
    auto p = bfs(a, cur, inside, [&](std::uint32_t, const Edge& e) { return (e.marks & bit) != 0; });
    // Record every mark taken on the way (only the last edge is checked, fine).
    w.cycle.insert(w.cycle.end(), p->first.begin(), p->first.end());
    need &= ~bit;
    cur = p->second;
  }
  // Close the cycle back to target (at least one edge).
  if (cur != target || w.cycle.empty()) {
    auto p = bfs(a, cur, inside, [&](std::uint32_t, const Edge& e) { return e.dst == target; });
    w.cycle.insert(w.cycle.end(), p->first.begin(), p->first.end());
  }
  return w;
}

}  // namespace rtamp::automata
