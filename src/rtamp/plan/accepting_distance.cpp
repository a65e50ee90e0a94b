#include "rtamp/plan/accepting_distance.hpp"

#include <algorithm>
#include <functional>

namespace rtamp::plan {

bool AcceptingDistance::build(ProductGraph& g, std::size_t max_nodes, Budget& budget, SearchStats& stats) {
  ready_ = false;
  // Close the graph: node ids are dense, so expanding every id below size()
  // (which grows as it goes) reaches a fixed point.
  for (NodeId v = 0; v < g.size(); ++v) {
    if (g.expanded(v)) continue;
    g.expand(v);
    ++stats.successor_generations;
    ++stats.expanded;
    if (g.size() > max_nodes || budget.exhausted(g, stats.expanded)) return false;
  }
  const std::size_t n = g.size();
  rev_begin_.assign(n + 1, 0);
  for (NodeId v = 0; v < n; ++v)
    for (std::uint32_t e = g.edge_begin(v); e < g.edge_end(v); ++e) ++rev_begin_[g.edge(e).dst + 1];
  for (std::size_t v = 0; v < n; ++v) rev_begin_[v + 1] += rev_begin_[v];
  rev_.resize(rev_begin_[n]);
  cursor_.assign(rev_begin_.begin(), rev_begin_.end() - 1);
  for (NodeId v = 0; v < n; ++v)
    for (std::uint32_t e = g.edge_begin(v); e < g.edge_end(v); ++e) {
      const ProductEdge& pe = g.edge(e);
      rev_[cursor_[pe.dst]++] = {v, pe.cost};
    }
  dijkstra(g, false, to_);
  dijkstra(g, true, from_);
  ready_ = true;
  return true;
}

void AcceptingDistance::dijkstra(const ProductGraph& g, bool forward, std::vector<double>& d) {
  const std::size_t n = g.size();
  d.assign(n, kInf);
  heap_.clear();
  const auto later = std::greater<std::pair<double, NodeId>>{};
  // Seeds: the accepting nodes at 0 (state-based); transition-based, for
  // each accepting edge u -> v, v at 0 going forward and u at the edge's
  // cost going backward (to(n) counts the accepting edge itself).
  auto seed = [&](NodeId v, double c) {
    if (c < d[v]) d[v] = c, heap_.emplace_back(c, v);
  };
  for (NodeId v = 0; v < n; ++v) {
    if (g.accepting(v)) seed(v, 0);
    if (g.transition_based())
      for (std::uint32_t e = g.edge_begin(v); e < g.edge_end(v); ++e)
        if (g.accepting_edge(e)) forward ? seed(g.edge(e).dst, 0) : seed(v, g.edge(e).cost);
  }
  std::make_heap(heap_.begin(), heap_.end(), later);
  auto relax = [&](NodeId w, double c) {
    if (c < d[w]) {
      d[w] = c;
      heap_.emplace_back(c, w);
      std::push_heap(heap_.begin(), heap_.end(), later);
    }
  };
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const auto [c, v] = heap_.back();
    heap_.pop_back();
    if (c > d[v]) continue;
    if (forward) {
      for (std::uint32_t e = g.edge_begin(v); e < g.edge_end(v); ++e)
        relax(g.edge(e).dst, c + g.edge(e).cost);
    } else {
      for (std::uint32_t i = rev_begin_[v]; i < rev_begin_[v + 1]; ++i)
        relax(rev_[i].first, c + rev_[i].second);
    }
  }
}

double AcceptingDistance::return_bound(NodeId x, NodeId j, bool accepted) const {
  if (!accepted) return to_[x] + from_[j];
  // d(A, j) <= d(A, x) + d(x, j) and d(x, A) <= d(x, j) + d(j, A); from(x)
  // and to(j) are finite here (x was reached from an accepting node, j reaches one).
  double b = 0;
  if (from_[x] < kInf) b = std::max(b, from_[j] - from_[x]);
  if (to_[j] < kInf) b = std::max(b, to_[x] - to_[j]);
  return b;
}

std::size_t AcceptingDistance::bytes() const {
  return (to_.capacity() + from_.capacity()) * sizeof(double) +
         (rev_begin_.capacity() + cursor_.capacity()) * sizeof(std::uint32_t) +
         rev_.capacity() * sizeof(std::pair<NodeId, double>) +
         heap_.capacity() * sizeof(std::pair<double, NodeId>);
}

}  // namespace rtamp::plan
