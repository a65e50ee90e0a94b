// The product automaton PA = TS x BA of the paper's Definition 3, as an
// explicit graph that is built lazily ("partial graph construction",
// Section III.C) or all at once (expand_all: the "full graph construction"
// baseline). Nodes are (s, q) pairs; the edges of a node are generated the
// first time it is expanded: (s, q) -> (δ_t(s, a), q') for every enabled
// action a (stay included) and every BA edge q -> q' whose guard holds in
// L(s) (the label of the source state, as in Definition 3). Edge weight: the
// motion cost of a in s (0 for stay), from the model or the experience cache.
//
// Storage is flat: states as `words` uint64 per node in one array, the BA
// state, the edge range and the label per node in parallel arrays, edges in
// one array, and an open-addressing table of node ids (linear probing, load
// <= 1/2). Arrays grow geometrically; nothing is allocated per node.
// Only BA states that can reach an accepting cycle ("useful") are entered.
// Invariants: node ids are dense 0..size()-1 and never change; an expanded
// node's edges are edges_[edge_begin(n) .. edge_end(n)) and never change.
// The graph stays valid as long as the System, Labeling, Automaton and the
// cost model it was built with are unchanged (the Planner rebuilds it when the
// TS changes).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/task/labeling.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::plan {

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = std::numeric_limits<NodeId>::max();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct ProductEdge {
  NodeId dst = kNoNode;
  std::uint32_t action = 0;  // task::Action::packed()
  double cost = 0;
};

class ProductGraph {
 public:
  // `cache` may be null (costs straight from the model). All references must
  // outlive the graph.
  ProductGraph(const task::System& ts, const task::Labeling& labeling, const automata::Automaton& ba,
               const MotionCostModel& model, MotionCostCache* cache);

  const task::System& system() const { return *ts_; }
  const task::Labeling& labeling() const { return *lab_; }
  const automata::Automaton& automaton() const { return *ba_; }
  const MotionCostModel& model() const { return *model_; }

  // The node (s, q), added if new (kNoNode if q is not useful).
  NodeId find_or_add(const task::State& s, std::uint32_t q);
  NodeId find(const task::State& s, std::uint32_t q) const;

  std::size_t size() const { return q_.size(); }
  task::State state(NodeId n) const {
    task::State s;
    for (unsigned w = 0; w < words_; ++w) s.words[w] = states_[std::size_t{n} * words_ + w];
    return s;
  }
  std::uint32_t ba_state(NodeId n) const { return q_[n]; }
  bool accepting(NodeId n) const { return ba_->is_accepting_state(q_[n]); }
  bool useful(std::uint32_t q) const { return useful_[q]; }

  bool expanded(NodeId n) const { return edge_begin_[n] != kUnexpanded; }
  // Expands n if needed. Edge indices stay valid; references into edges() do
  // not survive a later expansion.
  void expand(NodeId n);
  std::uint32_t edge_begin(NodeId n) const { return edge_begin_[n]; }
  std::uint32_t edge_end(NodeId n) const { return edge_end_[n]; }
  const ProductEdge& edge(std::uint32_t i) const { return edges_[i]; }
  automata::Letter label(NodeId n) const { return labels_[n]; }  // valid once expanded

  // Full construction: expands every node reachable from `from`. Returns false
  // if it stopped because size() reached max_nodes or the deadline passed
  // (deadline_ns: steady_clock nanoseconds; 0 = none). `tick`, if given, is
  // called every 256 expansions with the current time (for progress reports).
  bool expand_all(NodeId from, std::size_t max_nodes, std::int64_t deadline_ns,
                  const std::function<void(std::int64_t now_ns)>& tick = {});
  // From several nodes (kNoNode entries are skipped).
  bool expand_all(const std::vector<NodeId>& from, std::size_t max_nodes, std::int64_t deadline_ns,
                  const std::function<void(std::int64_t now_ns)>& tick = {});

  // Per-node experience (Section III.C): a learned lower bound on the cost of
  // the best lasso from the node, and the minimum cost of a cycle through it
  // that contains an accepting node (exact, or a lower bound; for an
  // accepting node: its cheapest cycle).
  double learned(NodeId n) const { return n < learned_.size() ? learned_[n] : 0.0; }
  void learn(NodeId n, double v);
  // Costs are compared lexicographically as (motion cost, number of moves)
  // (ties in cost go to fewer moves; plan/search.hpp).
  struct Cycle {
    double lower = 0;         // no cycle through the node is lexicographically below (lower, moves)
    std::uint32_t moves = 0;
    bool exact = false;       // (lower, moves) is the cheapest cycle
  };
  // Cached heuristic value of a node (start-independent; NaN if unknown).
  double cached_h(NodeId n) const { return n < hcache_.size() ? hcache_[n] : kUnknownH; }
  void cache_h(NodeId n, double v) {
    if (hcache_.size() <= n) hcache_.resize(std::max<std::size_t>(size(), std::size_t{n} + 1) * 2, kUnknownH);
    hcache_[n] = v;
  }
  static constexpr double kUnknownH = -1.0;
  Cycle cycle(NodeId n) const { return n < cycles_.size() ? cycles_[n] : Cycle{}; }
  void set_cycle(NodeId n, Cycle c);
  // The edges of n's cheapest cycle, once a search has recorded them (set
  // with the exact cycle cost; appended to `out`). False if not recorded.
  bool cycle_path(NodeId n, std::vector<std::uint32_t>& out) const;
  void set_cycle_path(NodeId n, const std::vector<std::uint32_t>& edges);
  // Solved nodes (experience, "previously explored paths"): n lies on an
  // optimal lasso found by an earlier complete search, so learned(n) is the
  // exact cost of the best lasso from n, and via(n) is its first edge, or
  // kViaCycle if n is where that lasso's prefix joins its cycle (the cycle is
  // then exact in cycle(n)). Following via() from a solved node reaches such a
  // node through solved nodes only. Valid as long as the graph is.
  static constexpr std::uint32_t kNoVia = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::uint32_t kViaCycle = kNoVia - 1;
  std::uint32_t via(NodeId n) const { return n < via_.size() ? via_[n] : kNoVia; }
  bool solved(NodeId n) const { return via(n) != kNoVia; }
  // Marks n solved: the best lasso from n costs exactly `value` with `moves`
  // moves (the lexicographic minimum) and starts with edge `via`.
  void set_solved(NodeId n, double value, std::uint32_t moves, std::uint32_t via);
  std::uint32_t solved_moves(NodeId n) const { return n < solved_moves_.size() ? solved_moves_[n] : 0; }

  std::uint64_t expansions() const { return expansions_; }
  std::size_t num_edges() const { return edges_.size(); }
  std::size_t memory_bytes() const;

 private:
  static constexpr std::uint32_t kUnexpanded = std::numeric_limits<std::uint32_t>::max();
  std::uint64_t hash(const std::uint64_t* w, std::uint32_t q) const;
  void grow_table();

  const task::System* ts_;
  const task::Labeling* lab_;
  const automata::Automaton* ba_;
  const MotionCostModel* model_;
  MotionCostCache* cache_;
  unsigned words_;
  std::vector<bool> useful_;

  std::vector<std::uint64_t> states_;
  std::vector<std::uint32_t> q_;
  std::vector<std::uint32_t> edge_begin_, edge_end_;
  std::vector<automata::Letter> labels_;
  std::vector<ProductEdge> edges_;
  std::vector<std::uint32_t> table_;  // node id + 1, 0 = empty
  std::vector<double> learned_;
  std::vector<Cycle> cycles_;
  std::vector<double> hcache_;
  std::vector<std::uint32_t> via_;
  std::vector<std::uint32_t> solved_moves_;
  std::vector<std::uint32_t> cycle_at_;     // per node: 1 + offset in cycle_store_, 0 = none
  std::vector<std::uint32_t> cycle_store_;  // length, then the edges, per recorded cycle
  std::vector<std::uint32_t> succ_q_;  // scratch: BA successors of the node being expanded
  std::uint64_t expansions_ = 0;
};

}  // namespace rtamp::plan
