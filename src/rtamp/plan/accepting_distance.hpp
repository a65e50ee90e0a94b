// Distances to and from the accepting nodes of a product graph that is closed
// (every node expanded), for bounds on cycles where the chain bound has none
// (systems with containers): to(n) = the least cost of a path from n to an
// accepting node, from(n) = the least cost of a path from one to n (both 0 at
// accepting nodes, +inf where there is none). Transition-based: to(n) = the
// least cost of a path from n through an accepting edge (the edge included),
// from(n) = the least cost of a path from an accepting edge's end to n: the
// accepting set is then the accepting edges, and the bounds below hold alike. Every cycle through a
// non-accepting J that passes an accepting node costs at least to(J) +
// from(J); a cycle search's way from x back to J, before it has passed an
// accepting node, at least to(x) + from(J), and after, at least from(J) −
// from(x) and to(x) − to(J) (triangle inequalities through the accepting
// set). docs/planning.md "Cycles bounded through the accepting set".
// Invariants: built only when the whole graph could be closed within a node
// cap and the query's budget, so the distances are exact in the product;
// the arrays are sized once per build, nothing is allocated per node.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "rtamp/plan/plan.hpp"
#include "rtamp/plan/product_graph.hpp"
#include "rtamp/plan/termination.hpp"

namespace rtamp::plan {

class AcceptingDistance {
 public:
  // Forgets the last build (ready() is false).
  void clear() { ready_ = false; }
  // Expands every node of `g` (the graph closes) unless it would pass
  // `max_nodes` or the budget runs out, then computes the distances. False
  // (and not ready) when it stopped; the nodes it expanded stay in the graph.
  bool build(ProductGraph& g, std::size_t max_nodes, Budget& budget, SearchStats& stats);
  bool ready() const { return ready_; }
  double to(NodeId n) const { return to_[n]; }
  double from(NodeId n) const { return from_[n]; }
  // A lower bound on every cycle (>= 1 step) through n that passes an accepting node.
  double cycle_bound(NodeId n) const { return to_[n] + from_[n]; }
  // A lower bound on the rest of a cycle search's way from x back to its
  // join node j; `accepted`: the way has passed an accepting node.
  double return_bound(NodeId x, NodeId j, bool accepted) const;
  std::size_t bytes() const;

 private:
  // Multi-source Dijkstra from the accepting nodes into d, along the edges
  // (forward) or against them (backward, over the reverse arrays).
  void dijkstra(const ProductGraph& g, bool forward, std::vector<double>& d);

  bool ready_ = false;
  std::vector<double> to_, from_;
  std::vector<std::uint32_t> rev_begin_, cursor_;  // reverse edges: CSR over destinations
  std::vector<std::pair<NodeId, double>> rev_;     // (source, cost)
  std::vector<std::pair<double, NodeId>> heap_;
};

}  // namespace rtamp::plan
