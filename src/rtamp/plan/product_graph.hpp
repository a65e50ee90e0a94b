// The product automaton PA = TS x BA of the paper's Definition 3, as an
// explicit graph that is built lazily ("partial graph construction",
// Section III.C) or all at once (expand_all: the "full graph construction"
// baseline). Nodes are (s, q) pairs; the edges of a node are generated the
// first time it is expanded: (s, q) -> (δ_t(s, a), q') for every enabled
// action a (stay included) and every BA edge q -> q' whose guard holds in
// L(s) (the label of the source state, as in Definition 3). Edge weight: the
// motion cost of a in s (0 for stay), from the model or the motion-cost cache,
// checked as it is taken (plan/cost_check.hpp: NaN or negative throws
// rtamp::Error naming the edge; a move the model prices at +infinity, one it
// cannot do, gets no edge).
//
// Storage is flat: states as `words` uint64 per node in one array, the BA
// state, the edge range and the label per node in parallel arrays, edges in
// one array, and an open-addressing table of node ids (linear probing, load
// <= 1/2). Arrays grow geometrically; nothing is allocated per node.
// Only BA states that can reach an accepting cycle ("useful") are entered.
// Acceptance is on edges, generalized: each edge carries the acceptance sets
// it counts for (Automaton::cycle_marks — state-based: {0} when it enters an
// accepting node; a transition-based automaton's marks), and a cycle is
// accepting iff its edges carry every set between them (all_marks()). Where
// several automaton edges q -> q' hold in a node's label, the product has one
// edge per maximal mark set among them (a superset is always as good), so a
// one-set automaton gets one edge per q'. accepting_edge(i): edge i carries
// some set — every accepting cycle takes such an edge, and so does the rest
// of a cycle that has not yet taken every set, which is what the bounds use.
// Invariants: node ids are dense 0..size()-1 and never change; an expanded
// node's edges are edges_[edge_begin(n) .. edge_end(n)) and never change.
// The graph stays valid as long as the System, Labeling, Automaton and the
// cost model it was built with are unchanged (the Planner rebuilds it when the
// TS changes). It holds only the product; what searches learn about its nodes
// (bounds, cycles, solved paths) is kept in plan/experience.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/plan/motion_cost_cache.hpp"
#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/task/labeling.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::plan {

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = std::numeric_limits<NodeId>::max();
inline constexpr double kInf = std::numeric_limits<double>::infinity();
// The most acceptance sets a product accepts on (its cycle searches keep one
// layer per subset); the Planner degeneralizes an automaton with more.
inline constexpr std::uint32_t kMaxProductSets = 4;

struct ProductEdge {
  NodeId dst = kNoNode;
  std::uint32_t action = 0;  // task::Action::packed()
  double cost = 0;
};

class ProductGraph {
 public:
  // `cache` may be null (costs straight from the model). All references must
  // outlive the graph. Throws std::invalid_argument for an automaton with
  // more than kMaxProductSets sets.
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
  // n's automaton state is accepting (state-based automata; never for a
  // transition-based one, whose acceptance is on edges only).
  bool accepting(NodeId n) const { return ba_->is_accepting_state(q_[n]); }
  bool transition_based() const { return !ba_->state_based; }
  // The acceptance sets a cycle must take between its edges (1: Büchi).
  automata::Marks all_marks() const { return all_marks_; }
  // The sets edge i counts for (see the header comment).
  automata::Marks edge_marks(std::uint32_t i) const {
    return ba_->state_based ? (accepting(edges_[i].dst) ? 1u : 0u) : edge_marks_[i];
  }
  // Edge i carries some set.
  bool accepting_edge(std::uint32_t i) const { return edge_marks(i) != 0; }
  // Where the lasso search prices a cycle as soon as it reaches the node:
  // state-based, an accepting node; transition-based, an expanded node an
  // accepting edge leaves (a cycle taking that edge passes through it).
  bool accepting_anchor(NodeId n) const {
    if (ba_->state_based) return accepting(n);
    if (!expanded(n)) return false;
    for (std::uint32_t e = edge_begin_[n]; e < edge_end_[n]; ++e)
      if (edge_marks_[e]) return true;
    return false;
  }
  // The automaton the search's bounds read: the graph's own, except that a
  // generalized one (two or more sets) is given as one set that an edge
  // carries when it carries any — every accepting cycle, and the rest of
  // every cycle not yet through all sets, takes such an edge, so a bound
  // computed on it holds for the generalized search too.
  const automata::Automaton& bound_automaton() const { return union_ ? *union_ : *ba_; }
  bool useful(std::uint32_t q) const { return useful_[q]; }
  // q lies on an accepting automaton cycle: only nodes in such states can lie
  // on a lasso's cycle (automata/accepting_cycles.hpp).
  bool on_accepting_cycle(std::uint32_t q) const { return on_accepting_cycle_[q]; }

  bool expanded(NodeId n) const { return edge_begin_[n] != kUnexpanded; }
  // Expands n if needed. Edge indices stay valid; references into edges() do
  // not survive a later expansion.
  void expand(NodeId n);
  std::uint32_t edge_begin(NodeId n) const { return edge_begin_[n]; }
  std::uint32_t edge_end(NodeId n) const { return edge_end_[n]; }
  const ProductEdge& edge(std::uint32_t i) const { return edges_[i]; }
  automata::Letter label(NodeId n) const { return labels_[n]; }  // valid once expanded

  // Full construction: expands every node reachable from `from`. Returns false
  // if it stopped because size() reached max_nodes, memory_bytes() passed
  // max_bytes (checked every 256 expansions; 0 = none) or the deadline passed
  // (deadline_ns: steady_clock nanoseconds; 0 = none). `tick`, if given, is
  // called every 256 expansions with the current time (for progress reports).
  bool expand_all(NodeId from, std::size_t max_nodes, std::int64_t deadline_ns,
                  const std::function<void(std::int64_t now_ns)>& tick = {}, std::size_t max_bytes = 0);
  // From several nodes (kNoNode entries are skipped).
  bool expand_all(const std::vector<NodeId>& from, std::size_t max_nodes, std::int64_t deadline_ns,
                  const std::function<void(std::int64_t now_ns)>& tick = {}, std::size_t max_bytes = 0);

  std::uint64_t expansions() const { return expansions_; }
  // Moves the cost model priced +inf (not edges of the graph), since the graph was made.
  std::uint64_t impossible_moves() const { return impossible_moves_; }
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
  std::vector<bool> useful_, on_accepting_cycle_;

  std::vector<std::uint64_t> states_;
  std::vector<std::uint32_t> q_;
  std::vector<std::uint32_t> edge_begin_, edge_end_;
  std::vector<automata::Letter> labels_;
  std::vector<ProductEdge> edges_;
  std::vector<std::uint8_t> edge_marks_;  // per edge, transition-based automata only
  automata::Marks all_marks_ = 1;
  std::unique_ptr<automata::Automaton> union_;  // bound_automaton() of a generalized automaton
  std::vector<std::uint32_t> table_;  // node id + 1, 0 = empty
  std::vector<std::uint32_t> succ_q_;  // scratch: BA successors of the node being expanded
  std::vector<std::uint8_t> succ_marks_;  // scratch: per succ_q_ entry, the marks of the edge taken there
  std::uint64_t expansions_ = 0;
  std::uint64_t impossible_moves_ = 0;
};

}  // namespace rtamp::plan
