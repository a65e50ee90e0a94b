// An independent brute-force planner for tests: its own state representation
// (a vector of location names' indices), its own action rules (capacities and
// footprints: fit and the grid shares of the room rule, in doubles), its own
// motion-cost formulas written from docs/planning.md, labels from the world
// layer's reference evaluator, an explicit product with the automaton, and
// the minimum lasso cost by Dijkstra from the start plus, for every accepting
// node in order of distance, a Dijkstra for its cheapest cycle.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <queue>
#include <string>
#include <unordered_map>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario.hpp"

namespace oracle {

using rtamp::world::Vec3;

struct World {
  const rtamp::world::Scenario* sc;
  std::vector<std::string> things, locs;  // things: objects then containers; locs: regions then containers
  std::vector<std::string> classes;
  std::vector<bool> container;
  std::vector<int> cap;
  int R = 0;
  // Footprints (docs/planning.md "Footprints", its constants written out here):
  // a thing fits a location iff its x and y sizes are within the location's usable
  // extents (a region's size; a container's size less an 8 mm rim a side); room:
  // k things of a thing's size fit a location on a grid keeping d (3.5 cm; 1.5 cm
  // for containers) apart — per axis floor((u + d) / (s + d)) in a region,
  // 1 + 2 floor((u - s) / 2 / (s + d)) in a container; its area share is
  // (sx + p)(sy + p) / ((ux + 3.5 cm)(uy + 3.5 cm)), p = 3.5 cm for an object and
  // 2 * 1.5 cm - 3.5 cm for a container; it takes max(area share, just over
  // 1/(k + 1)), and the shares of the things directly at a location, with the new
  // one's, are at most 1. (The rule was once the area share alone.)
  static constexpr double kGap = 0.035, kTrayGap = 0.015, kRim = 0.008;
  std::vector<std::array<double, 2>> size;    // per thing
  std::vector<std::array<double, 2>> usable;  // per location

  // The share of location l that thing t takes.
  double share(std::size_t t, std::size_t l) const {
    const bool in_container = static_cast<int>(l) >= R;
    const bool fits = size[t][0] <= usable[l][0] + 1e-12 && size[t][1] <= usable[l][1] + 1e-12;
    const double d = container[t] ? std::min(kGap, kTrayGap) : kGap;
    const double p = container[t] ? 2 * std::min(kGap, kTrayGap) - kGap : kGap;
    double k = 1, cell = 1, room = 1;
    for (std::size_t a = 0; a < 2; ++a) {
      const double u = usable[l][a], sz = size[t][a];
      k *= in_container ? 1 + 2 * std::floor((u - sz) / 2 / (sz + d) + 1e-9)
                        : std::max(1.0, std::floor((u + d) / (sz + d) + 1e-9));
      cell *= std::max(0.0, sz + p);
      room *= u + kGap;
    }
    // The least share above 1/(k + 1), or the area share if larger; at most 1/k
    // (a thing that does not fit, as an initial placement may have it: its area share).
    if (!fits) return std::min(1.0, cell / room);
    return std::min(1 / k, std::max(std::min(1.0, cell / room), 1 / (k + 1) + 1e-8));
  }

  std::vector<std::vector<int>> groups;  // interchangeable objects (same class, never named)

  // Objects of one class that no atom of `atoms` names are interchangeable.
  void find_groups(const std::vector<std::string>& atoms) {
    rtamp::world::PropNames names;
    for (const auto& a : atoms) {
      const auto* prop = sc->find_proposition(a);
      try {
        rtamp::world::collect_names(prop ? prop->expr : rtamp::world::parse_prop_expr(a), names);
      } catch (...) {
      }
    }
    std::map<std::string, std::vector<int>> by_class;
    for (std::size_t t = 0; t < sc->objects.size(); ++t)
      if (!names.things.count(things[t])) by_class[classes[t]].push_back(static_cast<int>(t));
    for (auto& [c, g] : by_class)
      if (g.size() > 1) groups.push_back(g);
  }

  explicit World(const rtamp::world::Scenario& s) : sc(&s) {
    auto add_thing = [&](const std::string& name, const std::string& cls, bool is_container, const Vec3& sz) {
      things.push_back(name);
      classes.push_back(cls);
      container.push_back(is_container);
      size.push_back({sz[0], sz[1]});
    };
    auto add_loc = [&](const std::string& name, int capacity, double ux, double uy) {
      locs.push_back(name);
      cap.push_back(capacity);
      usable.push_back({ux, uy});
    };
    for (const auto& o : s.objects) add_thing(o.name, o.cls, false, o.size);
    for (const auto& c : s.containers) add_thing(c.name, c.cls, true, c.size);
    for (const auto& r : s.regions) add_loc(r.name, r.capacity, r.size[0], r.size[1]);
    R = static_cast<int>(s.regions.size());
    for (const auto& c : s.containers) add_loc(c.name, c.capacity, c.size[0] - 2 * kRim, c.size[1] - 2 * kRim);
  }
  int loc_index(const std::string& n) const {
    for (std::size_t i = 0; i < locs.size(); ++i)
      if (locs[i] == n) return static_cast<int>(i);
    return -1;
  }
  // Container location index -> thing index.
  int thing_of(int loc) const { return static_cast<int>(sc->objects.size()) + (loc - R); }
};

struct St {
  std::vector<int> loc;
  int hand = -1;  // -1 home
  bool operator==(const St&) const = default;
};

inline St canonical(const World& w, St s) {
  for (const auto& g : w.groups) {
    std::vector<int> v;
    for (int t : g) v.push_back(s.loc[static_cast<std::size_t>(t)]);
    std::sort(v.begin(), v.end());
    for (std::size_t i = 0; i < g.size(); ++i) s.loc[static_cast<std::size_t>(g[i])] = v[i];
  }
  return s;
}

inline Vec3 point(const World& w, const St& s, int loc) {
  if (loc < 0) {
    const auto& b = w.sc->robot.base;
    return {b[0], b[1], b[2] + 0.5};
  }
  if (loc < w.R) return w.sc->regions[static_cast<std::size_t>(loc)].center;
  const int region = s.loc[static_cast<std::size_t>(w.thing_of(loc))];
  return w.sc->regions[static_cast<std::size_t>(region)].center;
}

inline double dist(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

inline double move_cost(const World& w, const St& s, int thing, int to, const std::string& model) {
  if (model == "unit") return 1;
  const Vec3 p = point(w, s, s.loc[static_cast<std::size_t>(thing)]);
  const Vec3 t = point(w, s, to);
  if (model == "region") return dist(p, t);
  return dist(point(w, s, s.hand), p) + dist(p, t);
}

// Legal moves: (thing, to) pairs.
inline std::vector<std::pair<int, int>> moves(const World& w, const St& s) {
  std::vector<std::pair<int, int>> out;
  std::vector<int> count(w.locs.size(), 0);
  std::vector<double> used(w.locs.size(), 0.0);
  for (std::size_t t = 0; t < s.loc.size(); ++t) {
    ++count[static_cast<std::size_t>(s.loc[t])];
    used[static_cast<std::size_t>(s.loc[t])] += w.share(t, static_cast<std::size_t>(s.loc[t]));
  }
  for (std::size_t t = 0; t < w.things.size(); ++t)
    for (int l = 0; l < static_cast<int>(w.locs.size()); ++l) {
      const auto li = static_cast<std::size_t>(l);
      if (l == s.loc[t]) continue;
      if (w.container[t] && l >= w.R) continue;
      if (count[li] >= w.cap[li]) continue;
      if (w.size[t][0] > w.usable[li][0] + 1e-12 || w.size[t][1] > w.usable[li][1] + 1e-12) continue;  // does not fit
      if (used[li] + w.share(t, li) > 1 + 1e-9) continue;                                             // no room
      out.emplace_back(static_cast<int>(t), l);
    }
  return out;
}

inline rtamp::world::Placement placement(const World& w, const St& s) {
  rtamp::world::Placement p;
  for (std::size_t t = 0; t < w.things.size(); ++t)
    p.set(w.things[t], w.locs[static_cast<std::size_t>(s.loc[t])], w.classes[t], w.container[t]);
  return p;
}

// Truth of each automaton atom in s.
inline rtamp::automata::Letter label(const World& w, const St& s, const rtamp::automata::Automaton& ba) {
  const auto p = placement(w, s);
  rtamp::automata::Letter l = 0;
  for (std::size_t i = 0; i < ba.atoms.size(); ++i) {
    const auto* prop = w.sc->find_proposition(ba.atoms[i]);
    const rtamp::world::PropExpr e = prop ? prop->expr : rtamp::world::parse_prop_expr(ba.atoms[i]);
    if (rtamp::world::evaluate(e, p)) l |= rtamp::automata::Letter{1} << i;
  }
  return l;
}

inline St start(const World& w, const rtamp::world::Placement& p, const std::string& hand) {
  St s;
  for (const auto& t : w.things) s.loc.push_back(w.loc_index(*p.location_of(t)));
  s.hand = hand.empty() || hand == "home" ? -1 : w.loc_index(hand);
  return s;
}

// The product graph of (TS, BA) from a start, built by brute force.
// With `symmetry`, states that differ by a permutation of interchangeable
// objects are one node (the quotient the planner searches). Node 0 is the start.
struct Product {
  struct Node {
    St s;
    std::uint32_t q;
  };
  std::vector<Node> nodes;
  std::vector<std::vector<std::pair<int, double>>> adj;
  std::vector<std::vector<int>> adj_moves;  // per edge of adj: 1 for a move, 0 for stay
  std::vector<std::vector<rtamp::automata::Marks>> adj_marks;  // per edge of adj: Automaton::cycle_marks

  // `q0`: the automaton state of the start node (default: the initial state).
  Product(const rtamp::world::Scenario& sc, const rtamp::world::Placement& p, const std::string& hand,
          const rtamp::automata::Automaton& ba, const std::string& model, bool symmetry = true,
          std::optional<std::uint32_t> q0 = {}) {
    World w(sc);
    if (symmetry) w.find_groups(ba.atoms);
    std::map<std::pair<std::vector<int>, std::pair<int, std::uint32_t>>, int> index;
    auto id = [&](const St& s0, std::uint32_t q) {
      const St s = canonical(w, s0);
      auto key = std::make_pair(s.loc, std::make_pair(s.hand, q));
      auto it = index.find(key);
      if (it != index.end()) return it->second;
      const int n = static_cast<int>(nodes.size());
      index.emplace(key, n);
      nodes.push_back({s, q});
      adj.emplace_back();
      adj_moves.emplace_back();
      adj_marks.emplace_back();
      return n;
    };
    id(start(w, p, hand), q0 ? *q0 : ba.initial);
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const St s = nodes[n].s;
      const std::uint32_t q = nodes[n].q;
      const auto l = label(w, s, ba);
      for (const auto& e : ba.edges[q]) {
        if (!e.guard.matches(l)) continue;
        const int a = id(s, e.dst);
        adj[n].emplace_back(a, 0.0);
        adj_moves[n].push_back(0);
        adj_marks[n].push_back(ba.cycle_marks(e));
        for (auto [t, to] : moves(w, s)) {
          St s2 = s;
          const double c = move_cost(w, s, t, to, model);
          s2.loc[static_cast<std::size_t>(t)] = to;
          s2.hand = to;
          const int b = id(s2, e.dst);
          adj[n].emplace_back(b, c);
          adj_moves[n].push_back(1);
          adj_marks[n].push_back(ba.cycle_marks(e));
        }
      }
    }
  }

  // Distances from src; with skip_src, paths of at least one step (src's own
  // entry is then the cheapest cycle through it).
  std::vector<double> dijkstra(int src, bool skip_src) const {
    std::vector<double> d(nodes.size(), INFINITY);
    using QI = std::pair<double, int>;
    std::priority_queue<QI, std::vector<QI>, std::greater<QI>> pq;
    if (skip_src) {
      for (auto [m, c] : adj[static_cast<std::size_t>(src)])
        if (c < d[static_cast<std::size_t>(m)]) {
          d[static_cast<std::size_t>(m)] = c;
          pq.push({c, m});
        }
    } else {
      d[static_cast<std::size_t>(src)] = 0;
      pq.push({0, src});
    }
    while (!pq.empty()) {
      auto [dv, v] = pq.top();
      pq.pop();
      if (dv > d[static_cast<std::size_t>(v)]) continue;
      if (skip_src && v == src) continue;  // reached the source again: do not go on from it
      for (auto [m, c] : adj[static_cast<std::size_t>(v)])
        if (dv + c < d[static_cast<std::size_t>(m)]) {
          d[static_cast<std::size_t>(m)] = dv + c;
          pq.push({dv + c, m});
        }
    }
    return d;
  }

  // dijkstra() in the order (cost, moves), costs equal within 1e-9
  // (label-correcting: a node is taken again whenever its label improves).
  using Lex = std::pair<double, int>;
  static bool lex_less(const Lex& a, const Lex& b) {
    return a.first < b.first - 1e-9 || (a.first <= b.first + 1e-9 && a.second < b.second);
  }
  std::vector<Lex> lex_dijkstra(int src, bool skip_src) const {
    std::vector<Lex> d(nodes.size(), Lex{INFINITY, 0});
    using QI = std::pair<Lex, int>;
    std::priority_queue<QI, std::vector<QI>, std::greater<QI>> pq;
    auto relax = [&](int v, const Lex& dv) {
      const auto& out = adj[static_cast<std::size_t>(v)];
      for (std::size_t i = 0; i < out.size(); ++i) {
        const int m = out[i].first;
        const Lex nd{dv.first + out[i].second, dv.second + adj_moves[static_cast<std::size_t>(v)][i]};
        if (lex_less(nd, d[static_cast<std::size_t>(m)])) {
          d[static_cast<std::size_t>(m)] = nd;
          pq.push({nd, m});
        }
      }
    };
    if (skip_src) {
      relax(src, Lex{0, 0});
    } else {
      d[static_cast<std::size_t>(src)] = {0, 0};
      pq.push({{0, 0}, src});
    }
    while (!pq.empty()) {
      auto [dv, v] = pq.top();
      pq.pop();
      if (dv != d[static_cast<std::size_t>(v)]) continue;
      if (skip_src && v == src) continue;
      relax(v, dv);
    }
    return d;
  }
  // Multi-source: node v starts with label init[v] (INFINITY: not a source).
  std::vector<Lex> lex_dijkstra_multi(const std::vector<Lex>& init) const {
    std::vector<Lex> d = init;
    using QI = std::pair<Lex, int>;
    std::priority_queue<QI, std::vector<QI>, std::greater<QI>> pq;
    for (std::size_t v = 0; v < d.size(); ++v)
      if (d[v].first < INFINITY) pq.push({d[v], static_cast<int>(v)});
    while (!pq.empty()) {
      auto [dv, v] = pq.top();
      pq.pop();
      if (dv != d[static_cast<std::size_t>(v)]) continue;
      const auto& out = adj[static_cast<std::size_t>(v)];
      for (std::size_t i = 0; i < out.size(); ++i) {
        const auto m = static_cast<std::size_t>(out[i].first);
        const Lex nd{dv.first + out[i].second, dv.second + adj_moves[static_cast<std::size_t>(v)][i]};
        if (lex_less(nd, d[m])) {
          d[m] = nd;
          pq.push({nd, out[i].first});
        }
      }
    }
    return d;
  }
};

// The least lasso in the order (cost, number of moves) from (start, q0)
// (default: the initial state): among the cheapest lassos, the fewest moves;
// nullopt if there is none. A lasso is a path from the start to a node v and
// a cycle (>= 1 step) through v that contains an accepting node N, costing
// d(start, v) + d(v, N) + d(N, v) (v = N: d(start, N) + the cheapest cycle
// through N). For each accepting N, in order of d(start, N) (a lower bound:
// d(start, v) + d(v, N) >= d(start, N)): a search from N gives d(N, v), and a
// second one from every v at once, each starting with label
// d(start, v) + d(N, v), reaches N with the least lasso through N.
// join_anywhere = false: only lassos whose cycle starts at N (v = N), the
// planner's lasso shape before prefixes could join anywhere.
inline std::optional<std::pair<double, int>> min_lasso_lex(const rtamp::world::Scenario& sc,
                                                           const rtamp::world::Placement& p, const std::string& hand,
                                                           const rtamp::automata::Automaton& ba,
                                                           const std::string& model,
                                                           std::optional<std::uint32_t> q0 = {},
                                                           bool join_anywhere = true) {
  using Lex = Product::Lex;
  const Product g(sc, p, hand, ba, model, true, q0);
  const std::size_t N = g.nodes.size();
  const auto d0 = g.lex_dijkstra(0, false);
  std::vector<int> acc;
  for (std::size_t n = 0; n < N; ++n)
    if (ba.is_accepting_state(g.nodes[n].q) && d0[n].first < INFINITY) acc.push_back(static_cast<int>(n));
  std::sort(acc.begin(), acc.end(), [&](int a, int b) {
    return Product::lex_less(d0[static_cast<std::size_t>(a)], d0[static_cast<std::size_t>(b)]);
  });
  std::optional<Lex> best;
  auto plus = [](const Lex& a, const Lex& b) { return Lex{a.first + b.first, a.second + b.second}; };
  for (int n : acc) {
    const auto un = static_cast<std::size_t>(n);
    if (best && !Product::lex_less(d0[un], *best)) break;
    const auto from_n = g.lex_dijkstra(n, true);  // from_n[n]: the cheapest cycle through n
    Lex here{INFINITY, 0};
    if (from_n[un].first < INFINITY) here = plus(d0[un], from_n[un]);
    if (join_anywhere) {
      std::vector<Lex> init(N, Lex{INFINITY, 0});
      for (std::size_t v = 0; v < N; ++v)
        if (v != un && d0[v].first < INFINITY && from_n[v].first < INFINITY) init[v] = plus(d0[v], from_n[v]);
      const auto back = g.lex_dijkstra_multi(init);
      if (Product::lex_less(back[un], here)) here = back[un];
    }
    if (here.first < INFINITY && (!best || Product::lex_less(here, *best))) best = here;
  }
  return best;
}

// The cheapest closed walk (>= 1 step, in the order (cost, moves)) from node
// v back to v whose edges carry every set `all` between them: a search over
// (node, the sets the walk has taken) from v's edges to (v, all).
inline Product::Lex cheapest_accepting_walk(const Product& g, int v, rtamp::automata::Marks all) {
  using Lex = Product::Lex;
  const std::size_t L = std::size_t{all} + 1;
  std::vector<Lex> d(g.nodes.size() * L, Lex{INFINITY, 0});
  using QI = std::pair<Lex, std::size_t>;
  std::priority_queue<QI, std::vector<QI>, std::greater<QI>> pq;
  const std::size_t goal = static_cast<std::size_t>(v) * L + all;
  auto relax = [&](std::size_t node, rtamp::automata::Marks taken, const Lex& dv) {
    for (std::size_t i = 0; i < g.adj[node].size(); ++i) {
      const std::size_t id = static_cast<std::size_t>(g.adj[node][i].first) * L + (taken | g.adj_marks[node][i]);
      const Lex nd{dv.first + g.adj[node][i].second, dv.second + g.adj_moves[node][i]};
      if (Product::lex_less(nd, d[id])) {
        d[id] = nd;
        pq.push({nd, id});
      }
    }
  };
  relax(static_cast<std::size_t>(v), 0, Lex{0, 0});
  while (!pq.empty()) {
    auto [dv, id] = pq.top();
    pq.pop();
    if (dv != d[id] || id == goal) continue;
    relax(id / L, static_cast<rtamp::automata::Marks>(id % L), dv);
  }
  return d[goal];
}

// The least lasso in the order (cost, moves) for an automaton of any form,
// by brute force on the definition of generalized Büchi acceptance
// (Automaton::cycle_marks): a path from (start, q0) to a node v, then a
// closed walk from v whose edges carry every acceptance set. Every v is
// tried, in order of d(start, v) (a lower bound on its lassos).
inline std::optional<Product::Lex> min_lasso_generalized_lex(const rtamp::world::Scenario& sc,
                                                             const rtamp::world::Placement& p,
                                                             const std::string& hand,
                                                             const rtamp::automata::Automaton& ba,
                                                             const std::string& model,
                                                             std::optional<std::uint32_t> q0 = {}) {
  using Lex = Product::Lex;
  const Product g(sc, p, hand, ba, model, true, q0);
  const auto d0 = g.lex_dijkstra(0, false);
  std::vector<int> order;
  for (std::size_t n = 0; n < g.nodes.size(); ++n)
    if (d0[n].first < INFINITY) order.push_back(static_cast<int>(n));
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return Product::lex_less(d0[static_cast<std::size_t>(a)], d0[static_cast<std::size_t>(b)]);
  });
  std::optional<Lex> best;
  for (const int v : order) {
    const Lex& dv = d0[static_cast<std::size_t>(v)];
    if (best && !Product::lex_less(dv, *best)) break;
    const Lex c = cheapest_accepting_walk(g, v, ba.cycle_marks_all());
    if (c.first >= INFINITY) continue;
    const Lex here{dv.first + c.first, dv.second + c.second};
    if (!best || Product::lex_less(here, *best)) best = here;
  }
  return best;
}

// The least lasso cost (min_lasso_lex's cost), or nullopt if there is none.
inline std::optional<double> min_lasso(const rtamp::world::Scenario& sc, const rtamp::world::Placement& p,
                                       const std::string& hand, const rtamp::automata::Automaton& ba,
                                       const std::string& model, bool /*symmetry*/ = true,
                                       std::optional<std::uint32_t> q0 = {}, bool join_anywhere = true) {
  const auto l = min_lasso_lex(sc, p, hand, ba, model, q0, join_anywhere);
  if (!l) return std::nullopt;
  return l->first;
}

// Minimum over the start automaton states `qs` of min_lasso (the multi-source
// optimum), or nullopt if there is none from any of them.
inline std::optional<double> min_lasso_from(const rtamp::world::Scenario& sc, const rtamp::world::Placement& p,
                                            const std::string& hand, const rtamp::automata::Automaton& ba,
                                            const std::string& model, const std::vector<std::uint32_t>& qs) {
  std::optional<double> best;
  for (std::uint32_t q : qs) {
    const auto c = min_lasso(sc, p, hand, ba, model, true, q);
    if (c && (!best || *c < *best)) best = c;
  }
  return best;
}

}  // namespace oracle
