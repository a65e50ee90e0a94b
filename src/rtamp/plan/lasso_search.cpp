#include "rtamp/plan/lasso_search.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace rtamp::plan {

namespace {
bool is_move(const ProductEdge& e) { return e.action != task::Action::stay().packed(); }
// maybe_bound_cycles: once the query has expanded as many nodes as the graph
// holds (deterministic), if the closed graph is at most this many times as big.
constexpr std::size_t kGrowth = 8;
}  // namespace

void LassoSearch::initialize(ProductGraph& g, Experience& x, const std::vector<NodeId>& starts, Heuristic& h,
                             const LassoConfig& config, const Termination& stop) {
  g_ = &g;
  x_ = &x;
  h_ = &h;
  config_ = config;
  budget_.start(stop, [this] {
    return g_->memory_bytes() + x_->memory_bytes() + x_->costs().bytes() + memory_bytes();
  });
  cycles_.begin(g, x, config.cycle_heuristic ? &h : nullptr, budget_);
  dist_.clear();
  dist_tried_ = false;
  join_searches_ = 0;
  status_ = SearchStatus::InProgress;
  best_ = kInf;
  best_m_ = kManyMoves;
  early_ = Early::Waiting;
  best_node_ = kNoNode;
  best_solved_ = false;
  SearchSpace& S = prefix_;
  S.begin(g.size());
  cand_.clear();
  closed_list_.clear();
  // Multi-source: every start node at g = 0 (duplicates are harmless).
  for (const NodeId init : starts) {
    if (init == kNoNode || S.seen(init)) continue;
    S.mark_seen(init);
    S.g[init] = 0;
    S.m[init] = 0;
    S.h[init] = h.estimate(g, init);
    S.parent[init] = kNoNode;
    S.closed[init] = 0;
    if (S.h[init] < kInf) S.push({S.h[init], 0.0, init, 0});
    offer_solved(init, 0.0, 0);
  }
}

// Experience: a solved node m completes a lasso of cost g(m) + learned(m).
void LassoSearch::offer_solved(NodeId m, double gm, std::uint32_t mm) {
  if (!config_.learn || !x_->solved(m)) return;
  const double c = gm + x_->learned(m);
  const std::uint32_t cm = mm + x_->solved_moves(m);
  if (lex_less(c, cm, best_, best_m_)) {
    best_ = c;
    best_m_ = cm;
    best_node_ = m;
    best_solved_ = true;
  }
}

// The lasso with its cycle through n: the cheapest cycle through n and an
// accepting node, below what would beat the incumbent. False if the budget ran out.
bool LassoSearch::try_cycle(NodeId n, SearchStats& stats) {
  const SearchSpace& S = prefix_;
  return try_cycle(n, {best_ - S.g[n], best_m_ > S.m[n] ? best_m_ - S.m[n] : 0}, stats);
}

bool LassoSearch::try_cycle(NodeId n, PathCost bound, SearchStats& stats) {
  const SearchSpace& S = prefix_;
  const PathCost c = cycles_.cheapest(n, bound, stats);
  if (c.c < kInf && lex_less(S.g[n] + c.c, S.m[n] + c.m, best_, best_m_)) {
    best_ = S.g[n] + c.c;
    best_m_ = S.m[n] + c.m;
    best_node_ = n;
    best_solved_ = false;
  }
  return budget_.reason() == StopReason::None;
}

void LassoSearch::expand(NodeId n, SearchStats& stats) {
  ProductGraph& g = *g_;
  SearchSpace& S = prefix_;
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
    const std::uint32_t nm = mn + (is_move(pe) ? 1 : 0);
    if (!S.seen(m)) {
      S.mark_seen(m);
      S.h[m] = h_->estimate(g, m);
    } else if (!lex_less(ng, nm, S.g[m], S.m[m])) {
      continue;
    }
    S.reach(m, ng, nm, n, e);
    if (S.h[m] < kInf) S.push({ng + S.h[m], ng, m, nm});
    offer_solved(m, ng, nm);
  }
}

SearchStatus LassoSearch::stop(SearchStatus s) { return status_ = s; }

void LassoSearch::maybe_bound_cycles(NodeId n, SearchStats& stats) {
  ++join_searches_;
  if (dist_tried_ || !config_.cycle_heuristic || join_searches_ < config_.accepting_bounds_after) return;
  if (h_->cycle_bound(*g_, n) > 0) return;  // the chain bound bounds this cycle already
  const std::size_t size = g_->size();
  const bool at_once = config_.accepting_bounds_after == 0;
  if (!at_once && stats.expanded < size) return;
  dist_tried_ = true;
  // Closing the graph may multiply it by at most kGrowth.
  const std::size_t cap = at_once ? std::numeric_limits<std::size_t>::max() : kGrowth * size;
  if (dist_.build(*g_, cap, budget_, stats)) cycles_.use(&dist_);
}

bool LassoSearch::rekeyed(const SearchItem& it) {
  if (!dist_.ready()) return false;
  const double key = it.g + dist_.cycle_bound(it.n);
  if (!(key > it.f + kCostEps)) return false;
  if (key < kInf) {
    cand_.push_back({key, it.g, it.n, it.m});
    std::push_heap(cand_.begin(), cand_.end(), after);
  }
  return true;
}

SearchStatus LassoSearch::early_candidate(const SearchItem& it, SearchStats& stats) {
  const double lower = it.f - it.g;  // the key's bound on the candidate's cycle
  if (!(lower > 0)) return try_cycle(it.n, stats) ? status_ : stop(SearchStatus::Stopped);  // unbounded
  const double bound = 2 * lower;
  if (!try_cycle(it.n, {bound, kManyMoves}, stats)) return stop(SearchStatus::Stopped);
  if (best_ >= kInf) {  // none below the bound (the table keeps it): wait again, keyed by it
    cand_.push_back({it.g + bound, it.g, it.n, it.m});
    std::push_heap(cand_.begin(), cand_.end(), after);
    // A search that could not move anything (the heuristic ruled out every
    // way back, e.g. to the hand at home) says nothing of the others.
    if (!cycles_.moved()) return status_;
    // Perhaps there is no lasso: no more searches before one, and what lies on
    // no accepting cycle is found at once.
    early_ = Early::Off;
    cycles_.classify_pending(stats);
  }
  return status_;
}

SearchStatus LassoSearch::step(SearchStats& stats) {
  if (status_ != SearchStatus::InProgress) return status_;
  SearchSpace& S = prefix_;
  // Join candidates wait in their own heap, keyed by g + a lower bound on
  // their cycle; they are taken once an incumbent exists and their key is the
  // least (until then the prefix search finds a first lasso through an
  // accepting node).
  while (!cand_.empty() && S.stale(cand_.front())) {
    std::pop_heap(cand_.begin(), cand_.end(), after);
    cand_.pop_back();
  }
  if (!cand_.empty() &&
      (S.heap.empty() || ((best_ < kInf || early_ == Early::On) && after(S.heap.front(), cand_.front())))) {
    std::pop_heap(cand_.begin(), cand_.end(), after);
    const SearchItem it = cand_.back();
    cand_.pop_back();
    if (rekeyed(it)) return status_;
    if (best_ >= kInf && !S.heap.empty()) return early_candidate(it, stats);
    if (it.f > best_ + kCostEps) return stop(SearchStatus::Finished);
    if (!lex_less(it.f, it.m, best_, best_m_)) return status_;
    maybe_bound_cycles(it.n, stats);
    if (budget_.reason() != StopReason::None) return stop(SearchStatus::Stopped);
    if (rekeyed(it)) return status_;
    return try_cycle(it.n, stats) ? status_ : stop(SearchStatus::Stopped);
  }
  if (S.heap.empty()) return stop(SearchStatus::Finished);
  const SearchItem it = S.pop();
  const NodeId n = it.n;
  if (S.stale(it)) return status_;
  if (it.f > best_ + kCostEps) return stop(SearchStatus::Finished);
  if (!lex_less(it.f, it.m, best_, best_m_)) return status_;  // nothing through n beats the incumbent
  if (S.closed[n]) return status_;
  S.closed[n] = 1;
  closed_list_.push_back(n);
  budget_.set_progress(best_, it.f);
  // Nothing through a solved node beats the lasso it already offered.
  if (config_.learn && x_->solved(n)) return status_;
  ++stats.expanded;
  ProductGraph& g = *g_;
  if (g.transition_based() && !g.expanded(n)) {  // accepting_anchor reads n's edges
    g.expand(n);
    ++stats.successor_generations;
  }
  if (g.accepting_anchor(n)) {
    if (!try_cycle(n, stats)) return stop(SearchStatus::Stopped);
    if (early_ == Early::Waiting) {
      // Early searches need a lower bound on the cycle itself to set theirs.
      early_ = best_ >= kInf && config_.cycle_heuristic && h_->cycle_bound(g, n) > 0 ? Early::On : Early::Off;
      if (early_ == Early::Off) cycles_.classify_pending(stats);
    }
  } else if (g.on_accepting_cycle(g.ba_state(n))) {
    // A join candidate: its cycle costs at least what the table knows and at
    // least the way to acceptance (h).
    const Experience::Cycle known = x_->cycle(n);
    if (known.exact) {
      if (!try_cycle(n, stats)) return stop(SearchStatus::Stopped);  // no search: the table has it
    } else {
      const double lb = std::max({known.lower, S.h[n], config_.cycle_heuristic ? h_->cycle_bound(g, n) : 0.0,
                                  dist_.ready() ? dist_.cycle_bound(n) : 0.0});
      const double key = S.g[n] + lb;
      if (key < kInf) {
        cand_.push_back({key, S.g[n], n, S.m[n]});
        std::push_heap(cand_.begin(), cand_.end(), after);
      }
      // Transition-based: no start node is accepting, whose search would
      // decide the early searches (a state-based start often is); the first
      // candidate whose cycle the heuristic bounds from below starts them.
      if (early_ == Early::Waiting && g.transition_based() && config_.cycle_heuristic &&
          h_->cycle_bound(g, n) > 0)
        early_ = Early::On;
    }
  }
  expand(n, stats);
  budget_.set_progress(best_, it.f);
  return budget_.exhausted(g, stats.expanded) ? stop(SearchStatus::Stopped) : status_;
}

// Removes closed walks from a path of edges starting at `from` (a path made of
// a search-tree branch and a solved path may meet itself only through
// zero-cost edges, e.g. stay edges between BA states). Paths are short.
void LassoSearch::drop_loops(NodeId from, std::vector<std::uint32_t>& edges) {
  path_nodes_.assign(1, from);
  std::size_t kept = 0;
  for (std::uint32_t e : edges) {
    const NodeId d = g_->edge(e).dst;
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

LassoResult LassoSearch::result(SearchStats& stats) {
  const ProductGraph& g = *g_;
  const SearchSpace& S = prefix_;
  LassoResult r;
  r.hit_node_limit = budget_.reason() == StopReason::NodeLimit;
  r.hit_time_limit = budget_.reason() == StopReason::TimeLimit;
  r.hit_memory_limit = budget_.reason() == StopReason::MemoryLimit;
  if (best_node_ != kNoNode) {
    r.found = true;
    NodeId init = best_node_;
    for (; S.parent[init] != kNoNode; init = S.parent[init]) r.prefix_edges.push_back(S.pedge[init]);
    std::reverse(r.prefix_edges.begin(), r.prefix_edges.end());
    r.start = init;
    NodeId acc = best_node_;
    if (best_solved_) {
      // Follow the solved path to its accepting node (it ends: Experience::record_search).
      for (std::uint32_t e = x_->via(acc); e != Experience::kViaCycle; e = x_->via(acc)) {
        r.prefix_edges.push_back(e);
        acc = g.edge(e).dst;
        if (++stats.reused_path_edges > g.size()) throw std::logic_error("LassoSearch: solved path loops");
      }
      drop_loops(init, r.prefix_edges);
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
  if (config_.learn && status_ == SearchStatus::Finished) {
    closed_costs_.clear();
    for (NodeId m : closed_list_) closed_costs_.emplace_back(m, S.g[m]);
    steps_.clear();
    NodeId x = r.start;
    for (std::uint32_t e : r.prefix_edges) {
      steps_.push_back({x, e, g.edge(e).cost, is_move(g.edge(e))});
      x = g.edge(e).dst;
    }
    std::uint32_t cycle_moves = 0;
    for (std::uint32_t e : r.cycle_edges) cycle_moves += is_move(g.edge(e)) ? 1 : 0;
    x_->record_search(closed_costs_, r.found, steps_, r.cycle_start, r.cycle_cost, cycle_moves);
  }
  return r;
}

LassoResult LassoSearch::run(ProductGraph& g, Experience& x, const std::vector<NodeId>& starts, Heuristic& h,
                             const LassoConfig& config, const Termination& stop, SearchStats& stats) {
  initialize(g, x, starts, h, config, stop);
  while (step(stats) == SearchStatus::InProgress) {
  }
  return result(stats);
}

LassoResult LassoSearch::run(ProductGraph& g, Experience& x, NodeId init, Heuristic& h, const LassoConfig& config,
                             const Termination& stop, SearchStats& stats) {
  starts_.assign(1, init);
  return run(g, x, starts_, h, config, stop, stats);
}

}  // namespace rtamp::plan
