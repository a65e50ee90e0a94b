#include "rtamp/plan/cycle_search.hpp"

#include <algorithm>
#include <bit>

namespace rtamp::plan {

void CycleSearch::begin(ProductGraph& g, Experience& x, Heuristic* h, Budget& budget) {
  g_ = &g;
  x_ = &x;
  h_ = h;
  budget_ = &budget;
  dist_ = nullptr;
  pending_ = kNoNode;
  if (++scc_gen_ == 0) {  // wrapped: clear the stamps once
    std::fill(scc_stamp_.begin(), scc_stamp_.end(), 0);
    scc_gen_ = 1;
  }
}

void CycleSearch::grow_scc_tables() {
  if (scc_stamp_.size() >= g_->size()) return;
  const std::size_t cap = std::max<std::size_t>(g_->size(), 2 * scc_stamp_.size());
  scc_index_.resize(cap);
  scc_low_.resize(cap);
  scc_state_.resize(cap);
  scc_stamp_.resize(cap, 0);
}

int CycleSearch::on_accepting_cycle(NodeId n, SearchStats& stats) {
  ProductGraph& g = *g_;
  grow_scc_tables();
  if (scc_stamp_[n] == scc_gen_ && scc_state_[n] >= 2) return scc_state_[n] == 3;
  auto open = [&](NodeId v) {
    if (!g.expanded(v)) {
      g.expand(v);
      ++stats.successor_generations;
      grow_scc_tables();
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
      if (budget_->exhausted(g, stats.expanded)) {
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
    automata::Marks inside = 0;
    bool edge = scc_stack_.end() - first > 1;
    // The sets the edges inside the SCC carry (its members are the stack from root up).
    for (auto it = first; it != scc_stack_.end() && inside != g.all_marks(); ++it)
      for (std::uint32_t x = g.edge_begin(*it); x < g.edge_end(*it); ++x) {
        const NodeId w = g.edge(x).dst;
        if (scc_stamp_[w] == scc_gen_ && scc_state_[w] == 1 && scc_index_[w] >= scc_index_[root])
          inside |= g.edge_marks(x);
      }
    const bool acc = inside == g.all_marks();
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

// Relaxes edge e out of search node `from` (node << shift_ | the sets the path
// has taken; start_ stands for the target itself).
void CycleSearch::relax(NodeId from, std::uint32_t e) {
  ProductGraph& g = *g_;
  SearchSpace& S = space_;
  const ProductEdge& pe = g.edge(e);
  const NodeId layer = (from & layer_mask()) | g.edge_marks(e);
  const NodeId m = (pe.dst << shift_) | layer;
  const double ng = (from == start_ ? 0.0 : S.g[from]) + pe.cost;
  const std::uint32_t nm = (from == start_ ? 0 : S.m[from]) + (pe.action != task::Action::stay().packed() ? 1 : 0);
  if (pe.dst == target_) {  // back at the target: a cycle if it went through an accepting node
    if (m == goal_ && lex_less(ng, nm, best_.c, best_.m)) {
      best_ = {ng, nm};
      found_ = true;
      S.parent[goal_] = from;
      S.pedge[goal_] = e;
    }
    return;
  }
  S.ensure(g.size() << shift_);
  if (!S.seen(m)) {
    S.mark_seen(m);
    S.closed[m] = 0;
    S.h[m] =
        !h_ ? 0.0
            : std::max({state_distance_bound(g.system(), g.model(), g.state(pe.dst), target_state_),
                        h_->walk_bound(g, pe.dst, target_q_),
                        h_->return_bound(g, pe.dst, target_, layer == g.all_marks()),
                        dist_ && dist_->ready() ? dist_->return_bound(pe.dst, target_, layer == g.all_marks()) : 0.0});
  } else if (!lex_less(ng, nm, S.g[m], S.m[m])) {
    return;
  }
  S.reach(m, ng, nm, from, e);
  const double f = ng + S.h[m];
  if (f < kInf && lex_less(f, nm, best_.c, best_.m)) {
    S.push({f, ng, m, nm});
    moved_ = moved_ || nm > 0;
  }
}

void CycleSearch::classify_pending(SearchStats& stats) {
  if (pending_ != kNoNode) (void)on_accepting_cycle(pending_, stats);
  pending_ = kNoNode;
}

PathCost CycleSearch::cheapest(NodeId n, PathCost bound, SearchStats& stats) {
  ProductGraph& g = *g_;
  const Experience::Cycle known = x_->cycle(n);
  if (known.exact)
    return lex_less(known.lower, known.moves, bound.c, bound.m) ? PathCost{known.lower, known.moves} : kNoPathCost;
  if (!lex_less(known.lower, known.moves, bound.c, bound.m)) return kNoPathCost;
  ++stats.cycle_searches;
  moved_ = false;
  target_ = n;
  target_state_ = g.state(n);
  target_q_ = g.ba_state(n);
  shift_ = static_cast<unsigned>(std::bit_width(g.all_marks()));  // one layer per subset of the sets
  start_ = (n << shift_) | (g.accepting(n) ? 1u : 0u);
  goal_ = (n << shift_) | g.all_marks();
  best_ = bound;  // the incumbent: a cycle below it is sought; lowered by each one found
  found_ = false;
  SearchSpace& S = space_;
  S.begin(g.size() << shift_);
  if (!g.expanded(n)) {
    g.expand(n);
    ++stats.successor_generations;
  }
  for (std::uint32_t e = g.edge_begin(n); e < g.edge_end(n); ++e) relax(start_, e);
  while (!S.heap.empty()) {
    const SearchItem it = S.pop();
    if (S.stale(it)) continue;
    if (it.f > best_.c + kCostEps) break;
    if (!lex_less(it.f, it.m, best_.c, best_.m)) continue;  // cannot beat the incumbent
    if (S.closed[it.n]) continue;
    S.closed[it.n] = 1;
    ++stats.expanded;
    const NodeId x = it.n >> shift_;
    if (!g.expanded(x)) {
      g.expand(x);
      ++stats.successor_generations;
    }
    for (std::uint32_t e = g.edge_begin(x); e < g.edge_end(x); ++e) relax(it.n, e);
    if (budget_->exhausted(g, stats.expanded)) return kNoPathCost;
  }
  if (found_) {
    x_->set_cycle(n, {best_.c, best_.m, true});
    path_.clear();
    NodeId cur = goal_;
    do {
      path_.push_back(S.pedge[cur]);
      cur = S.parent[cur];
    } while (cur != start_);
    std::reverse(path_.begin(), path_.end());
    x_->set_cycle_path(n, path_);  // kept from this search: the lasso is rebuilt from it
    return best_;
  }
  x_->set_cycle(n, {bound.c, bound.m, false});  // bound is above `known` (checked on entry)
  // No cycle at all through n (no incumbent bounded the search): classify
  // everything reachable from n at once — unless the heuristic ruled out
  // every way back that moves something (e.g. to a node with the hand at
  // home): the search then cost a few stays, and a classification would
  // visit the whole graph for this one node; it waits (classify_pending).
  if (bound.c >= kInf) {
    if (moved_)
      (void)on_accepting_cycle(n, stats);
    else if (pending_ == kNoNode)
      pending_ = n;
  }
  return kNoPathCost;
}

}  // namespace rtamp::plan
