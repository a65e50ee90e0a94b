// A* with experience (paper Section III.C): everything the planner reuses
// from one query to the next, in one place.
//
//  - The motion-cost cache (MotionCostCache, plan/motion_cost_cache.hpp):
//    costs of moves computed so far ("we cache the motion cost of edges newly
//    explored so far"). Its keys hold no node ids, so it survives TS rebuilds;
//    the planner uses it only for models whose costs are expensive() (ik).
//  - What searches learned about one product graph (plan/product_graph.hpp),
//    indexed by its node ids and valid as long as that graph is (the planner
//    keeps the graph while the TS is unchanged and calls forget_graph() when
//    it drops it):
//      learned bounds: a lower bound on the cost of the best lasso from a node;
//      the cycle table: per node, the least cost of a cycle through it that
//        contains an accepting node — exact, or "none below (lower, moves)" —
//        and, once found exactly, the edges of that cycle;
//      solved paths ("previously explored paths"): nodes on an optimal lasso
//        of an earlier complete search, with the exact cost of their best
//        lasso and its first edge;
//      the guard heuristic's value per node (it does not depend on the start).
// Why each value stays correct across queries with other start nodes, and how
// the lasso search uses them: docs/planning.md; record_search() is how a
// finished search writes them back. A cold query (dijkstra, astar)
// gives its throw-away graph a fresh Experience, so its cycle table lives for
// that query only.
// Costs are compared lexicographically as (motion cost, number of moves).
// Tables grow on demand; a node never written reads as unknown (learned 0, no
// cycle known, not solved, heuristic unknown).
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "rtamp/plan/motion_cost_cache.hpp"

namespace rtamp::plan {

class Experience {
 public:
  using Node = std::uint32_t;  // a ProductGraph NodeId

  explicit Experience(unsigned cost_depends = kDependsAll) : costs_(cost_depends) {}

  MotionCostCache& costs() { return costs_; }
  const MotionCostCache& costs() const { return costs_; }

  // Forgets everything indexed by node (the graph was dropped); keeps the cost cache.
  void forget_graph();

  // Learned lower bound on the cost of the best lasso from n (0 if unknown);
  // learn() only raises it.
  double learned(Node n) const { return n < learned_.size() ? learned_[n] : 0.0; }
  void learn(Node n, double v);

  // The cycle table.
  struct Cycle {
    double lower = 0;         // no cycle through the node is lexicographically below (lower, moves)
    std::uint32_t moves = 0;
    bool exact = false;       // (lower, moves) is the cheapest cycle
  };
  Cycle cycle(Node n) const { return n < cycles_.size() ? cycles_[n] : Cycle{}; }
  void set_cycle(Node n, Cycle c);
  // The edges of n's cheapest cycle, once a search has recorded them (set
  // with the exact cycle cost; appended to `out`). False if not recorded.
  bool cycle_path(Node n, std::vector<std::uint32_t>& out) const;
  void set_cycle_path(Node n, const std::vector<std::uint32_t>& edges);

  // Solved nodes: n lies on an optimal lasso found by an earlier complete
  // search, so learned(n) is the exact cost of the best lasso from n, and
  // via(n) is its first edge, or kViaCycle if n is where that lasso's prefix
  // joins its cycle (the cycle is then exact in cycle(n)). Following via()
  // from a solved node reaches such a node through solved nodes only.
  static constexpr std::uint32_t kNoVia = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::uint32_t kViaCycle = kNoVia - 1;
  std::uint32_t via(Node n) const { return n < via_.size() ? via_[n] : kNoVia; }
  bool solved(Node n) const { return via(n) != kNoVia; }
  // Marks n solved: the best lasso from n costs exactly `value` with `moves`
  // moves (the lexicographic minimum) and starts with edge `via`.
  void set_solved(Node n, double value, std::uint32_t moves, std::uint32_t via);
  std::uint32_t solved_moves(Node n) const { return n < solved_moves_.size() ? solved_moves_[n] : 0; }

  // What one finished lasso search learned (total: its lasso's cost, kInf if
  // it found none — then none exists). Every closed node n not solved gets
  // learned(n) >= total - g(n), g(n) its cost from the start: a cheaper lasso
  // through n would have been found. With a lasso, every node of its prefix
  // (from the start, each with its edge) and the join node become solved: the
  // lasso is optimal in (cost, moves), so the rest of it achieves the best
  // value from each exactly. Nodes solved earlier keep their via edge, so via
  // chains only lead to nodes solved no later and, among nodes solved
  // together, along one simple path: following via() ends.
  struct PrefixStep {
    Node node;           // where the edge leaves from
    std::uint32_t edge;  // its index in the graph
    double cost;
    bool move;           // not a stay
  };
  void record_search(const std::vector<std::pair<Node, double>>& closed, bool found,
                     const std::vector<PrefixStep>& prefix, Node join, double cycle_cost, std::uint32_t cycle_moves);

  // The guard heuristic's value at n (kUnknownH if not computed yet).
  static constexpr double kUnknownH = -1.0;
  double cached_h(Node n) const { return n < hcache_.size() ? hcache_[n] : kUnknownH; }
  void cache_h(Node n, double v);

  // Bytes held by the per-node tables (the cost cache reports its own).
  std::size_t memory_bytes() const;

 private:
  MotionCostCache costs_;
  std::vector<double> learned_;
  std::vector<Cycle> cycles_;
  std::vector<double> hcache_;
  std::vector<std::uint32_t> via_;
  std::vector<std::uint32_t> solved_moves_;
  std::vector<std::uint32_t> cycle_at_;     // per node: 1 + offset in cycle_store_, 0 = none
  std::vector<std::uint32_t> cycle_store_;  // length, then the edges, per recorded cycle
};

}  // namespace rtamp::plan
