#include "rtamp/plan/search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace rtamp::plan {

namespace {
constexpr double kEps = 1e-9;
constexpr std::uint32_t kManyMoves = ~std::uint32_t{0};
// (c1, m1) below (c2, m2) in the order (cost, moves), costs equal within kEps.
bool lex_less(double c1, std::uint32_t m1, double c2, std::uint32_t m2) {
  return c1 < c2 - kEps || (c1 <= c2 + kEps && m1 < m2);
}
bool heap_less(const auto& a, const auto& b) {  // max-heap comparator: "a after b"
  if (a.f != b.f) return a.f > b.f;
  if (a.g != b.g) return a.g < b.g;  // ties: larger g first (deeper)
  return a.m > b.m;                  // then fewer moves
}
}  // namespace

std::int64_t steady_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

const char* to_string(Algorithm a) {
  switch (a) {
    case Algorithm::Dijkstra: return "dijkstra";
    case Algorithm::AStar: return "astar";
    case Algorithm::AStarExperience: return "astar-exp";
  }
  return "?";
}

const NameTable<GraphConstruction>& graph_constructions() {
  static const NameTable<GraphConstruction> t = {
      {"partial", GraphConstruction::Partial, "product successors built as the search expands them (the paper's)"},
      {"full", GraphConstruction::Full, "the whole product built first (the baseline)"},
  };
  return t;
}

const char* to_string(GraphConstruction g) { return name_of(graph_constructions(), g); }

void LassoSearch::Space::ensure(std::size_t n) {
  if (stamp.size() >= n) return;
  const std::size_t cap = std::max<std::size_t>(n, stamp.size() * 2);
  g.grow(cap, false);
  m.grow(cap, false);
  h.grow(cap, false);
  parent.grow(cap, false);
  pedge.grow(cap, false);
  stamp.grow(cap, true);
  closed.grow(cap, false);
}

void LassoSearch::Space::begin(std::size_t n) {
  ensure(std::max<std::size_t>(n, 256));
  if (++gen == 0) {  // wrapped: clear the stamps once
    std::fill(stamp.p.get(), stamp.p.get() + stamp.size(), 0u);
    gen = 1;
  }
  heap.clear();
}

void LassoSearch::Space::push(Item it) {
  heap.push_back(it);
  std::push_heap(heap.begin(), heap.end(), [](const Item& a, const Item& b) { return heap_less(a, b); });
}

LassoSearch::Item LassoSearch::Space::pop() {
  std::pop_heap(heap.begin(), heap.end(), [](const Item& a, const Item& b) { return heap_less(a, b); });
  Item it = heap.back();
  heap.pop_back();
  return it;
}

std::size_t LassoSearch::Space::bytes() const {
  return g.size() * 8 + m.size() * 4 + h.size() * 8 + parent.size() * 4 + pedge.size() * 4 + stamp.size() * 4 +
         closed.size() + heap.capacity() * sizeof(Item);
}

// Removes closed walks from a path of edges starting at `from` (a path made of
// a search-tree branch and a solved path may meet itself only through
// zero-cost edges, e.g. stay edges between BA states). Paths are short.
void LassoSearch::drop_loops(const ProductGraph& g, NodeId from, std::vector<std::uint32_t>& edges) {
  path_nodes_.assign(1, from);
  std::size_t kept = 0;
  for (std::uint32_t e : edges) {
    const NodeId d = g.edge(e).dst;
    auto seen = std::find(path_nodes_.begin(), path_nodes_.end(), d);
    if (seen != path_nodes_.end()) {  // back at an earlier node: forget the loop
      const auto keep = static_cast<std::size_t>(seen - path_nodes_.begin());
      path_nodes_.resize(keep + 1);
      kept = keep;
      continue;
    }
    edges[kept++] = e;
    path_nodes_.push_back(d);
  }
  edges.resize(kept);
}

bool LassoSearch::out_of_budget(const ProductGraph& g, const SearchStats& stats, LassoResult& r) {
  const SearchLimits& limits = stop_->limits;
  const std::int64_t deadline_ns = stop_->deadline_ns;
  if (g.size() > limits.max_nodes) {
    r.hit_node_limit = true;
    return true;
  }
  if ((++ticks_ & 127) != 0) return false;
  if (limits.max_memory_bytes &&
      g.memory_bytes() + x_->memory_bytes() + x_->costs().bytes() + memory_bytes() > limits.max_memory_bytes) {
    r.hit_memory_limit = true;
    return true;
  }
  if (deadline_ns || limits.on_progress) {
    const std::int64_t now = steady_now_ns();
    if (deadline_ns && now > deadline_ns) {
      r.hit_time_limit = true;
      return true;
    }
    if (limits.on_progress && now >= next_progress_ns_) {
      next_progress_ns_ = now + limits.progress_interval_ns();
      SearchProgress p;
      p.graph_nodes = g.size();
      p.expanded = stats.expanded;
      p.best = progress_best_;
      p.bound = progress_bound_;
      p.seconds = double(now - start_ns_) * 1e-9;
      limits.on_progress(p);
    }
  }
  return r.hit_time_limit;
}

int LassoSearch::on_accepting_cycle(ProductGraph& g, NodeId n, SearchStats& stats, LassoResult& r) {
  auto grow = [&] {
    if (scc_stamp_.size() >= g.size()) return;
    const std::size_t cap = std::max<std::size_t>(g.size(), 2 * scc_stamp_.size());
    scc_index_.resize(cap);
    scc_low_.resize(cap);
    scc_state_.resize(cap);
    scc_stamp_.resize(cap, 0);
  };
  grow();
  if (scc_stamp_[n] == scc_gen_ && scc_state_[n] >= 2) return scc_state_[n] == 3;
  auto open = [&](NodeId v) {
    if (!g.expanded(v)) {
      g.expand(v);
      ++stats.successor_generations;
      grow();
    }
    ++stats.expanded;
    scc_stamp_[v] = scc_gen_;
    scc_index_[v] = scc_low_[v] = scc_counter_++;
    scc_state_[v] = 1;
    scc_stack_.push_back(v);
    scc_frames_.emplace_back(v, g.edge_begin(v));
  };
  scc_frames_.clear();
  scc_stack_.clear();
  open(n);
  while (!scc_frames_.empty()) {
    auto& [v, e] = scc_frames_.back();
    if (e < g.edge_end(v)) {
      const NodeId w = g.edge(e++).dst;
      if (scc_stamp_[w] != scc_gen_) {
        open(w);  // may grow scc_frames_: v, e are not used after this
      } else if (scc_state_[w] == 1) {
        scc_low_[v] = std::min(scc_low_[v], scc_index_[w]);
      }
      if (out_of_budget(g, stats, r)) {
        for (NodeId x : scc_stack_) scc_stamp_[x] = scc_gen_ - 1;  // unfinished: forget them
        return -1;
      }
      continue;
    }
    const NodeId root = v;
    scc_frames_.pop_back();
    if (!scc_frames_.empty()) {
      const NodeId parent = scc_frames_.back().first;
      scc_low_[parent] = std::min(scc_low_[parent], scc_low_[root]);
    }
    if (scc_low_[root] != scc_index_[root]) continue;
    // root's SCC is the stack from root up.
    const auto first = std::find(scc_stack_.rbegin(), scc_stack_.rend(), root).base() - 1;
    bool acc = false, edge = scc_stack_.end() - first > 1;
    for (auto it = first; it != scc_stack_.end(); ++it) acc = acc || g.accepting(*it);
    if (!edge)
      for (std::uint32_t x = g.edge_begin(root); x < g.edge_end(root) && !edge; ++x) edge = g.edge(x).dst == root;
    const bool yes = acc && edge;
    for (auto it = first; it != scc_stack_.end(); ++it) {
      scc_state_[*it] = yes ? 3 : 2;
      if (!yes) x_->set_cycle(*it, {kInf, kManyMoves, false});
    }
    scc_stack_.erase(first, scc_stack_.end());
  }
  return scc_state_[n] == 3;
}

LassoSearch::Cost LassoSearch::cycle(ProductGraph& g, NodeId n, Cost bound, SearchStats& stats, LassoResult& r) {
  Heuristic* const h = cycle_h_;
  const Experience::Cycle known = x_->cycle(n);
  if (known.exact)
    return lex_less(known.lower, known.moves, bound.c, bound.m) ? Cost{known.lower, known.moves} : kNoCost;
  if (!lex_less(known.lower, known.moves, bound.c, bound.m)) return kNoCost;
  ++stats.cycle_searches;
  const task::State target = g.state(n);
  const std::uint32_t target_q = g.ba_state(n);
  const std::uint32_t stay = task::Action::stay().packed();
  // Search space: (node, layer), id = 2 * node + layer; layer 1 once the
  // path has entered an accepting node (an accepting n starts in layer 1).
  // The cycle is found on the way back to (n, 1).
  const NodeId start = 2 * n + (g.accepting(n) ? 1 : 0), goal = 2 * n + 1;
  Space& S = cycle_;
  S.begin(2 * g.size());
  Cost best = bound;  // the incumbent: a cycle below it is sought; lowered by each one found
  bool found = false;
  auto relax = [&](NodeId from, std::uint32_t e) {
    const ProductEdge& pe = g.edge(e);
    const NodeId m = 2 * pe.dst + ((from & 1) | (g.accepting(pe.dst) ? 1 : 0));
    const double ng = (from == start ? 0.0 : S.g[from]) + pe.cost;
    const std::uint32_t nm = (from == start ? 0 : S.m[from]) + (pe.action != stay ? 1 : 0);
    if (pe.dst == n) {  // back at n: a cycle if it went through an accepting node
      if (m == goal && lex_less(ng, nm, best.c, best.m)) {
        best = {ng, nm};
        found = true;
        S.parent[goal] = from;
        S.pedge[goal] = e;
      }
      return;
    }
    S.ensure(2 * g.size());
    if (!S.seen(m)) {
      S.stamp[m] = S.gen;
      S.closed[m] = 0;
      S.h[m] = !h ? 0.0
                  : std::max({state_distance_bound(g.system(), g.model(), g.state(pe.dst), target),
                              h->walk_bound(g, pe.dst, target_q), h->return_bound(g, pe.dst, n, (m & 1) != 0)});
    } else if (!lex_less(ng, nm, S.g[m], S.m[m])) {
      return;
    }
    S.g[m] = ng;
    S.m[m] = nm;
    S.parent[m] = from;
    S.pedge[m] = e;
    S.closed[m] = 0;
    const double f = ng + S.h[m];
    if (f < kInf && lex_less(f, nm, best.c, best.m)) S.push({f, ng, m, nm});
  };
  if (!g.expanded(n)) {
    g.expand(n);
    ++stats.successor_generations;
  }
  for (std::uint32_t e = g.edge_begin(n); e < g.edge_end(n); ++e) relax(start, e);
  while (!S.heap.empty()) {
    const Item it = S.pop();
    if (it.g != S.g[it.n] || it.m != S.m[it.n]) continue;  // stale
    if (it.f > best.c + kEps) break;
    if (!lex_less(it.f, it.m, best.c, best.m)) continue;  // cannot beat the incumbent
    if (S.closed[it.n]) continue;
    S.closed[it.n] = 1;
    ++stats.expanded;
    const NodeId x = it.n / 2;
    if (!g.expanded(x)) {
      g.expand(x);
      ++stats.successor_generations;
    }
    for (std::uint32_t e = g.edge_begin(x); e < g.edge_end(x); ++e) relax(it.n, e);
    if (out_of_budget(g, stats, r)) return kNoCost;
  }
  if (found) {
    x_->set_cycle(n, {best.c, best.m, true});
    cycle_path_.clear();
    NodeId cur = goal;
    do {
      cycle_path_.push_back(S.pedge[cur]);
      cur = S.parent[cur];
    } while (cur != start);
    std::reverse(cycle_path_.begin(), cycle_path_.end());
    x_->set_cycle_path(n, cycle_path_);  // kept from this search: the lasso is rebuilt from it
    return best;
  }
  x_->set_cycle(n, {bound.c, bound.m, false});  // bound is above `known` (checked on entry)
  // No cycle at all through n (no incumbent bounded the search): n's SCC has
  // none, and neither may many nodes reachable from it. Classify them all at
  // once, so that they get no unbounded cycle search of their own (a query
  // without a lasso would otherwise search the graph once per node).
  if (bound.c >= kInf) (void)on_accepting_cycle(g, n, stats, r);
  return kNoCost;
}

LassoResult LassoSearch::run(ProductGraph& g, Experience& x, NodeId init, Heuristic& h, const LassoConfig& config,
                             const Termination& stop, SearchStats& stats) {
  starts_.assign(1, init);
  return run(g, x, starts_, h, config, stop, stats);
}

LassoResult LassoSearch::run(ProductGraph& g, Experience& experience, const std::vector<NodeId>& starts, Heuristic& h,
                             const LassoConfig& config, const Termination& stop, SearchStats& stats) {
  x_ = &experience;
  stop_ = &stop;
  cycle_h_ = config.cycle_heuristic ? &h : nullptr;
  const bool learn = config.learn;
  LassoResult r;
  start_ns_ = steady_now_ns();
  next_progress_ns_ = start_ns_ + stop.limits.progress_interval_ns();
  progress_best_ = kInf;
  progress_bound_ = 0;
  const std::uint32_t stay = task::Action::stay().packed();
  Space& S = prefix_;
  S.begin(g.size());
  cand_.clear();
  closed_list_.clear();
  if (++scc_gen_ == 0) {  // wrapped: clear the stamps once
    std::fill(scc_stamp_.begin(), scc_stamp_.end(), 0);
    scc_gen_ = 1;
  }
  double best = kInf;  // the incumbent lasso, (best, best_m) in the order (cost, moves)
  std::uint32_t best_m = kManyMoves;
  NodeId best_node = kNoNode;  // an accepting node, or (best_solved) a solved node
  bool best_solved = false;
  // Experience: a solved node m completes a lasso of cost g(m) + learned(m).
  auto offer_solved = [&](NodeId m, double gm, std::uint32_t mm) {
    if (!learn || !x_->solved(m)) return;
    const double c = gm + x_->learned(m);
    const std::uint32_t cm = mm + x_->solved_moves(m);
    if (lex_less(c, cm, best, best_m)) {
      best = c;
      best_m = cm;
      best_node = m;
      best_solved = true;
    }
  };

  // Multi-source: every start node at g = 0 (duplicates are harmless).
  for (const NodeId init : starts) {
    if (init == kNoNode || S.seen(init)) continue;
    S.stamp[init] = S.gen;
    S.g[init] = 0;
    S.m[init] = 0;
    S.h[init] = h.estimate(g, init);
    S.parent[init] = kNoNode;
    S.closed[init] = 0;
    if (S.h[init] < kInf) S.push({S.h[init], 0.0, init, 0});
    offer_solved(init, 0.0, 0);
  }
  // The lasso with its cycle through n: the cheapest cycle through n and an
  // accepting node (cycle()), below what would beat the incumbent.
  auto try_cycle = [&](NodeId n) {
    const Cost bound{best - S.g[n], best_m > S.m[n] ? best_m - S.m[n] : 0};
    const Cost c = cycle(g, n, bound, stats, r);
    if (c.c < kInf && lex_less(S.g[n] + c.c, S.m[n] + c.m, best, best_m)) {
      best = S.g[n] + c.c;
      best_m = S.m[n] + c.m;
      best_node = n;
      best_solved = false;
    }
    return !r.stopped();
  };
  auto cand_less = [](const Item& a, const Item& b) { return heap_less(a, b); };
  bool complete = true;
  for (;;) {
    // Join candidates (closed non-accepting nodes on automaton cycles through
    // acceptance) wait in their own heap, keyed by g + a lower bound on their
    // cycle; they are taken once an incumbent exists and their key is the
    // least (until then the prefix search finds a first lasso through an
    // accepting node as it always did).
    while (!cand_.empty() && (cand_.front().g != S.g[cand_.front().n] || cand_.front().m != S.m[cand_.front().n])) {
      std::pop_heap(cand_.begin(), cand_.end(), cand_less);
      cand_.pop_back();
    }
    const bool take_cand = !cand_.empty() && (S.heap.empty() || (best < kInf && heap_less(S.heap.front(), cand_.front())));
    if (take_cand) {
      std::pop_heap(cand_.begin(), cand_.end(), cand_less);
      const Item it = cand_.back();
      cand_.pop_back();
      if (it.f > best + kEps) break;
      if (!lex_less(it.f, it.m, best, best_m)) continue;
      if (!try_cycle(it.n)) {
        complete = false;
        break;
      }
      continue;
    }
    if (S.heap.empty()) break;
    const Item it = S.pop();
    const NodeId n = it.n;
    if (it.g != S.g[n] || it.m != S.m[n]) continue;  // stale
    if (it.f > best + kEps) break;
    if (!lex_less(it.f, it.m, best, best_m)) continue;  // nothing through n beats the incumbent
    if (S.closed[n]) continue;
    S.closed[n] = 1;
    closed_list_.push_back(n);
    progress_bound_ = it.f;
    // Nothing through a solved node beats the lasso it already offered.
    if (learn && x_->solved(n)) continue;
    ++stats.expanded;
    if (g.accepting(n)) {
      if (!try_cycle(n)) {
        complete = false;
        break;
      }
    } else if (g.on_accepting_cycle(g.ba_state(n))) {
      // A join candidate: its cycle costs at least what the table knows and
      // at least the way to acceptance (h).
      const Experience::Cycle known = x_->cycle(n);
      if (known.exact) {
        if (!try_cycle(n)) {  // no search: the table has it
          complete = false;
          break;
        }
      } else {
        const double lb = std::max({known.lower, S.h[n], cycle_h_ ? cycle_h_->cycle_bound(g, n) : 0.0});
        const double key = S.g[n] + lb;
        if (key < kInf) {
          cand_.push_back({key, S.g[n], n, S.m[n]});
          std::push_heap(cand_.begin(), cand_.end(), cand_less);
        }
      }
    }
    if (!g.expanded(n)) {
      g.expand(n);
      ++stats.successor_generations;
    }
    S.ensure(g.size());
    const double gn = S.g[n];
    const std::uint32_t mn = S.m[n];
    for (std::uint32_t e = g.edge_begin(n); e < g.edge_end(n); ++e) {
      const ProductEdge& pe = g.edge(e);
      const NodeId m = pe.dst;
      const double ng = gn + pe.cost;
      const std::uint32_t nm = mn + (pe.action != stay ? 1 : 0);
      if (!S.seen(m)) {
        S.stamp[m] = S.gen;
        S.h[m] = h.estimate(g, m);
      } else if (!lex_less(ng, nm, S.g[m], S.m[m])) {
        continue;
      }
      S.g[m] = ng;
      S.m[m] = nm;
      S.parent[m] = n;
      S.pedge[m] = e;
      S.closed[m] = 0;
      if (S.h[m] < kInf) S.push({ng + S.h[m], ng, m, nm});
      offer_solved(m, ng, nm);
    }
    progress_best_ = best;
    if (out_of_budget(g, stats, r)) {
      complete = false;
      break;
    }
  }
  if (best_node != kNoNode) {
    r.found = true;
    NodeId init = best_node;
    for (; S.parent[init] != kNoNode; init = S.parent[init]) r.prefix_edges.push_back(S.pedge[init]);
    std::reverse(r.prefix_edges.begin(), r.prefix_edges.end());
    r.start = init;
    NodeId acc = best_node;
    if (best_solved) {
      // Follow the solved path to its accepting node (terminates: see set_solved below).
      for (std::uint32_t e = x_->via(acc); e != Experience::kViaCycle; e = x_->via(acc)) {
        r.prefix_edges.push_back(e);
        acc = g.edge(e).dst;
        if (++stats.reused_path_edges > g.size()) throw std::logic_error("LassoSearch: solved path loops");
      }
      drop_loops(g, init, r.prefix_edges);
    }
    r.cycle_start = acc;
    r.prefix_cost = 0;
    for (std::uint32_t e : r.prefix_edges) r.prefix_cost += g.edge(e).cost;
    // Every exact entry of the cycle table was set by a search that found
    // its cycle and kept the path (this query's or, with experience, an
    // earlier one's on the same graph).
    if (!x_->cycle(acc).exact || !x_->cycle_path(acc, r.cycle_edges))
      throw std::logic_error("LassoSearch: the join node's cycle was not kept");
    r.cycle_cost = x_->cycle(acc).lower;
  }
  if (learn && complete && !r.stopped()) {
    const double total = r.found ? r.prefix_cost + r.cycle_cost : kInf;
    for (NodeId m : closed_list_)
      if (!x_->solved(m)) x_->learn(m, total - S.g[m]);
    if (r.found) {
      // The lasso is optimal in (cost, moves), so every node x on its prefix
      // has V(x) exactly (total, total moves) - (cost, moves of the prefix up
      // to x): the rest of the lasso achieves it, and V(x) >= C* - dist(init,
      // x) >= that (in the same order). Nodes solved earlier keep their via
      // edge, so via chains only lead to nodes solved no later and, among
      // nodes solved together, along one simple path: they end.
      std::uint32_t cycle_moves = 0;
      for (std::uint32_t e : r.cycle_edges) cycle_moves += g.edge(e).action != stay ? 1 : 0;
      std::uint32_t total_m = cycle_moves;
      for (std::uint32_t e : r.prefix_edges) total_m += g.edge(e).action != stay ? 1 : 0;
      double gx = 0;
      std::uint32_t mx = 0;
      NodeId x = r.start;
      for (std::uint32_t e : r.prefix_edges) {
        if (!x_->solved(x)) x_->set_solved(x, total - gx, total_m - mx, e);
        gx += g.edge(e).cost;
        mx += g.edge(e).action != stay ? 1 : 0;
        x = g.edge(e).dst;
      }
      if (!x_->solved(x)) x_->set_solved(x, r.cycle_cost, cycle_moves, Experience::kViaCycle);
    }
  }
  return r;
}

}  // namespace rtamp::plan
