// The cycle half of the lasso search: the cheapest cycle through a product node
// whose edges carry every acceptance set between them (ProductGraph::edge_marks;
// Büchi: it takes an accepting edge; state-based: passes an accepting node),
// in the order (cost, moves), below a bound. The search keeps one layer per
// subset of the sets the path has taken.
// Answers go into the experience's cycle table — exact with the cycle's path,
// or "none below (cost, moves)" — so no node's cycle is searched twice for the
// same bound on one graph. A node whose unbounded search finds nothing has its
// whole reachable part classified at once by Tarjan's SCCs (a node off every
// accepting cycle gets "none below infinity"), so a query without a lasso does
// not search the graph once per node. Why this is optimal: docs/planning.md.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "rtamp/plan/accepting_distance.hpp"
#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/plan.hpp"
#include "rtamp/plan/product_graph.hpp"
#include "rtamp/plan/search_space.hpp"
#include "rtamp/plan/termination.hpp"

namespace rtamp::plan {

class CycleSearch {
 public:
  // Starts a query on `g` with experience `x` and the cycles' heuristic `h`
  // (null: none); the budget is the query's.
  void begin(ProductGraph& g, Experience& x, Heuristic* h, Budget& budget);
  // With a heuristic, also bound the way back by `d` once it is ready (null: not).
  void use(const AcceptingDistance* d) { dist_ = d; }
  // The cheapest such cycle through n below `bound`, or kNoPathCost (none below
  // it, or the budget ran out). When found, its path is in the experience.
  PathCost cheapest(NodeId n, PathCost bound, SearchStats& stats);
  // Classifies what is reachable from the first node whose unbounded search
  // found nothing without moving anything (its classification was put off).
  void classify_pending(SearchStats& stats);
  // The last search opened a path that moves something (else the heuristic
  // ruled out every way back that does, e.g. to a node with the hand at home).
  bool moved() const { return moved_; }
  std::size_t bytes() const { return space_.bytes(); }

 private:
  // Whether n lies on any accepting cycle (1), not (0), or -1
  // when the budget ran out. Nodes classified earlier in the query are not
  // visited again (their SCCs are complete).
  int on_accepting_cycle(NodeId n, SearchStats& stats);
  void relax(NodeId from, std::uint32_t e);
  void grow_scc_tables();

  ProductGraph* g_ = nullptr;
  Experience* x_ = nullptr;
  Heuristic* h_ = nullptr;
  const AcceptingDistance* dist_ = nullptr;
  Budget* budget_ = nullptr;
  SearchSpace space_;
  std::vector<std::uint32_t> path_;
  // One cycle search: its target n (search ids: node << shift_ | the sets the
  // path has taken, all_marks() once it has taken every one; a state-based
  // start at an accepting node has its set), the incumbent.
  NodeId layer_mask() const { return (NodeId{1} << shift_) - 1; }
  unsigned shift_ = 1;
  NodeId target_ = kNoNode, start_ = kNoNode, goal_ = kNoNode;
  task::State target_state_;
  std::uint32_t target_q_ = 0;
  PathCost best_ = kNoPathCost;
  bool found_ = false;
  bool moved_ = false;  // the search opened a path that moves something
  NodeId pending_ = kNoNode;
  // on_accepting_cycle: per-node DFS index and lowlink (valid where
  // scc_stamp_ == scc_gen_), SCC state (0 open, 1 on the stack, 2 no accepting
  // cycle, 3 on one), the DFS frames (node, next edge) and the SCC stack.
  std::vector<std::uint32_t> scc_index_, scc_low_, scc_stamp_;
  std::vector<std::uint8_t> scc_state_;
  std::vector<std::pair<NodeId, std::uint32_t>> scc_frames_;
  std::vector<NodeId> scc_stack_;
  std::uint32_t scc_gen_ = 0, scc_counter_ = 0;
};

}  // namespace rtamp::plan
