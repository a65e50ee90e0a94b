// The lasso search (paper Section III.B): a minimum-cost lasso over all start
// nodes — a prefix to a node J and a cycle (>= 1 edge) back to J that takes
// an accepting edge (state-based: passes an accepting node), joined anywhere;
// cost prefix + cycle, ties broken by fewer moves. A best-first search over
// prefixes; at each anchor (ProductGraph::accepting_anchor: an accepting
// node, or a node an accepting edge leaves) and each join candidate (a node
// whose automaton state lies on an accepting cycle) the cycle search
// (plan/cycle_search.hpp) prices the cheapest cycle below the incumbent. In the shape of Fast Downward's engines: initialize(), then
// step() until it is not InProgress, then result(); run() does all three.
// Invariants: every heuristic is admissible (a cost bound, moves part 0);
// learned bounds and solved paths from the experience never exceed the true
// remaining cost, so they never cost optimality; a stopped search reports
// which limit hit and never "no plan"; no allocation per expanded node.
// The proof and the one kind of lasso not covered: docs/planning.md.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "rtamp/plan/cycle_search.hpp"
#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/plan.hpp"
#include "rtamp/plan/product_graph.hpp"
#include "rtamp/plan/search_space.hpp"
#include "rtamp/plan/termination.hpp"

namespace rtamp::plan {

// How a lasso search runs.
struct LassoConfig {
  bool cycle_heuristic = true;  // cycle searches use state_distance_bound and Heuristic::walk_bound (else 0)
  bool learn = false;           // use and store learned bounds and solved paths in the experience
  // Join candidates' cycle searches before the accepting-set bounds are
  // built (once the query has also expanded as many nodes as the graph
  // holds); 0: at the first, whatever they cost. Only with cycle_heuristic.
  std::uint32_t accepting_bounds_after = 1;
};

struct LassoResult {
  bool found = false;
  bool hit_node_limit = false, hit_time_limit = false, hit_memory_limit = false;
  bool stopped() const { return hit_node_limit || hit_time_limit || hit_memory_limit; }
  NodeId start = kNoNode;        // the start node the prefix leaves from
  NodeId cycle_start = kNoNode;  // J: where the prefix ends and the cycle begins and ends
  std::vector<std::uint32_t> prefix_edges, cycle_edges;  // edge indices in the graph
  double prefix_cost = 0, cycle_cost = 0;
};

enum class SearchStatus {
  InProgress,  // step() again
  Finished,    // the optimum is known (a lasso, or none exists)
  Stopped,     // a limit of the termination condition hit
};

class LassoSearch {
 public:
  // `x`: the experience of `g` (plan/experience.hpp); its cycle table is read
  // and written by every search (a cold query passes a fresh one), learned
  // bounds and solved paths only with config.learn. `starts`: the start nodes
  // (kNoNode entries are skipped). `g`, `x`, `h` and `stop` must outlive the search.
  void initialize(ProductGraph& g, Experience& x, const std::vector<NodeId>& starts, Heuristic& h,
                  const LassoConfig& config, const Termination& stop);
  // Takes one node off the open lists (a prefix expansion or a join candidate's cycle).
  SearchStatus step(SearchStats& stats);
  // The best lasso (found = false if none or stopped); with config.learn and a
  // finished search, writes what it learned into the experience.
  LassoResult result(SearchStats& stats);

  LassoResult run(ProductGraph& g, Experience& x, const std::vector<NodeId>& starts, Heuristic& h,
                  const LassoConfig& config, const Termination& stop, SearchStats& stats);
  LassoResult run(ProductGraph& g, Experience& x, NodeId init, Heuristic& h, const LassoConfig& config,
                  const Termination& stop, SearchStats& stats);
  std::size_t memory_bytes() const { return prefix_.bytes() + cycles_.bytes() + dist_.bytes(); }

 private:
  void offer_solved(NodeId m, double gm, std::uint32_t mm);
  // n's cheapest cycle below the incumbent (or `bound`); false when the budget ran out.
  bool try_cycle(NodeId n, SearchStats& stats);
  bool try_cycle(NodeId n, PathCost bound, SearchStats& stats);
  // Before the first lasso (see early_), a join candidate whose key is the least open one:
  // a cycle search bounded by twice its cycle's lower bound, and if none is
  // found below, the candidate waits again keyed by that bound.
  SearchStatus early_candidate(const SearchItem& it, SearchStats& stats);
  // Before candidate n's search: where the heuristic bounds its cycle by 0
  // (no chain bound), once the query has expanded as many nodes as the graph
  // holds, close the graph (at most kGrowth times its size) and bound
  // cycles through the accepting set (plan/accepting_distance.hpp).
  void maybe_bound_cycles(NodeId n, SearchStats& stats);
  // With those bounds, a candidate whose key was too low waits again, keyed
  // by them: true if `it` went back into the heap (or was dropped).
  bool rekeyed(const SearchItem& it);
  void expand(NodeId n, SearchStats& stats);
  SearchStatus stop(SearchStatus s);
  void drop_loops(NodeId from, std::vector<std::uint32_t>& edges);

  ProductGraph* g_ = nullptr;
  Experience* x_ = nullptr;
  Heuristic* h_ = nullptr;
  LassoConfig config_;
  Budget budget_;
  CycleSearch cycles_;
  AcceptingDistance dist_;
  bool dist_tried_ = false;
  std::uint32_t join_searches_ = 0;  // cycle searches of join candidates taken off their heap
  SearchSpace prefix_;
  // Join candidates may be searched before the first lasso (early_candidate)
  // once the first accepting node has had its cycle search, if that found
  // none and the heuristic bounds the cycle at that node from below (the
  // chain bound), until an early search finds nothing below its bound
  // (perhaps there is no lasso). Where they end or never start, a
  // classification the cycle search put off runs, so a query without a
  // lasso still learns at once which nodes lie on no accepting cycle.
  enum class Early { Waiting, On, Off };
  Early early_ = Early::Waiting;
  std::vector<SearchItem> cand_;  // join candidates, a heap keyed by g + a cycle lower bound
  std::vector<NodeId> closed_list_;
  std::vector<std::pair<NodeId, double>> closed_costs_;  // the write-back into the experience
  std::vector<Experience::PrefixStep> steps_;
  std::vector<NodeId> starts_, path_nodes_;
  SearchStatus status_ = SearchStatus::Finished;
  // The incumbent lasso, (best_, best_m_) in the order (cost, moves), ending at
  // best_node_: a node whose cycle is exact, or (best_solved_) a solved node.
  double best_ = kInf;
  std::uint32_t best_m_ = kManyMoves;
  NodeId best_node_ = kNoNode;
  bool best_solved_ = false;
};

}  // namespace rtamp::plan
