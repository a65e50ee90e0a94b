// ChainBound: a lower bound on the motion a lasso needs *between* the guards
// its automaton run reads, from the locations those guards force (part of the
// A* heuristic, plan/heuristic.hpp; admissibility argued below and checked by
// tests/plan/components_test.cpp against the brute force).
//
// A guard (cube) *forces* thing t to location L when one of its literals
// requires `t in L` or `all C in L` for t's class (through And, and Not/Or of
// unwanted literals). A path of the product reads one automaton edge per step,
// each edge's guard holding in the state where it is read. If it reads guards
// c, then later c', every thing that c forces to L and c' to L' != L moves from
// L to L' in between: with no containers every move carries exactly one thing,
// so that part of the path costs at least
//   D(c, c') = the model's carry_set_bound of those moves (L to L' for each
// such thing): at least the sum of their carry_bound(L, L'), and for euclid
// also the hand's way back between them (docs/planning.md "The hand's way
// back").
// Along a path, sum D over consecutive *forcing* guards (the segments do not
// overlap); the first forcing guard c1 costs LB(s, c1) from the start state s.
// A lasso through an accepting node with automaton state qa also pays, in its
// cycle, the D-sum around some automaton cycle through qa: kappa(qa) = the
// least such sum. Transition-based automata (acceptance on edges): qa ranges
// over the states an accepting edge enters, and kappa(qa) is the least D-sum
// of a closed walk from qa whose last step is an accepting edge (a lasso's
// cycle, turned to start where its accepting edge ends, is one); the walks
// below track "accepting seen" by the steps they take. The prefix may join the cycle anywhere (plan/lasso_search.hpp),
// so the path to qa and the cycle may share their stretch from the join to
// qa: the lasso costs at least max(path to qa, kappa(qa)), not their sum.
// So, with the graph G over (automaton state q, last forcing guard l or none)
// — an edge e with guard c: (q, l) -> (dst(e), c) weighted D(l, c) (LB for
// l = none) if c forces something, else (q, l) -> (dst(e), l) weighted 0 —
//   bound(s, q) = min over accepting qa of max(dist_G((q, none), (qa, .)), kappa(qa))
// is at most the cost of the best lasso from (s, q). Guards that force one
// thing to two places can never hold: their edges are left out.
// Everything but the first forcing guard's LB(s, c) is state-independent, so
// it is computed once: bound(s, q) = min(kappa of an accepting state reachable
// from q by non-forcing edges, min over the forcing edges c that start there
// of max(LB(s, c) + tail_path(c), tail_kappa(c))), tail_path(c) = the least
// D-distance in G from c to an accepting state, tail_kappa(c) = the least
// kappa of those reached (min over qa of the max is at least this). Enabled only without containers, when some
// D is positive, and when G is small (<= 48 nodes: set-up is a few Dijkstras
// on G per automaton state).
#pragma once

#include <cstdint>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/plan/product_graph.hpp"  // kInf
#include "rtamp/task/labeling.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::plan {

class ChainBound {
 public:
  // `useful`: per automaton state, whether it can reach an accepting cycle.
  ChainBound(const task::System& ts, const task::Labeling& lab, const automata::Automaton& ba,
             const MotionCostModel& model, const std::vector<bool>& useful);
  bool enabled() const { return enabled_; }
  // The forcing guards; bound() takes LB(s, cube) for each, in this order.
  const std::vector<automata::Cube>& forcing_cubes() const { return cubes_; }
  // D from s's locations to forcing_cubes()[c]'s: also a bound on the way
  // from s to a state where that guard holds (a first LB(s, c) for bound()).
  double from_state(const task::State& s, std::uint32_t c) const;
  // The bound above from automaton state q, given first[i] = LB(s, forcing_cubes()[i]).
  double bound(std::uint32_t q, const std::vector<double>& first) const;
  // No cycle of the product through an accepting node costs less (the least
  // kappa of an accepting state).
  double cycle_bound() const { return min_kappa_; }
  // No cycle of the product through (s, q) that contains an accepting node
  // costs less: the least D-sum around an automaton cycle through q and an
  // accepting state, with s's own locations as a forcing point at both ends
  // (every thing a guard on the way forces elsewhere leaves s's location and
  // comes back to it). 0 when disabled.
  double cycle_bound_at(const task::State& s, std::uint32_t q) const;
  // No path of >= 1 step from (s, q) to (target, target_q) that passes an
  // accepting node (unless `accepted`: one was passed already) costs less:
  // the least D-sum along an automaton walk from q to target_q, with s's
  // locations as the first forcing point and target's as the last
  // (cycle_bound_at is the case target = s). 0 when disabled. The cycle
  // search's heuristic back to its join node.
  double path_bound(const task::State& s, std::uint32_t q, const task::State& target, std::uint32_t target_q,
                    bool accepted) const;
  // No lasso from (s, q) costs less than the D-sum along prefix and cycle
  // together: the chain up to the prefix's last forcing guard, the stretch
  // through the join to the cycle's first one and the cycle's last stretch
  // back to the join (the model's join_set_bound), the cycle's chain between
  // (docs/planning.md "The join's stretch"; plan/chain_join.cpp). Returns
  // max(floor, that), stopping once it is known to be at most floor; `first`
  // as for bound().
  double join_bound(const task::State& s, std::uint32_t q, const std::vector<double>& first,
                    double floor) const;

 private:
  struct Arc {
    std::uint32_t to;
    double weight;
  };
  // Node (q, l) of G; l = n_forcing_ is "none". G has no arcs out of "none"
  // nodes along forcing edges (their weight LB(s, c) depends on the state;
  // bound() adds them).
  std::uint32_t node(std::uint32_t q, std::uint32_t l) const { return q * (n_forcing_ + 1) + l; }
  // Dijkstra on G from `src` into dist_; with skip_src, paths of at least one arc.
  void dijkstra(std::uint32_t src, bool skip_src);
  // The open node (not done) of least distance below `below`, or dist.size().
  static std::uint32_t least_open(const std::vector<double>& dist, const std::vector<std::uint8_t>& done,
                                  double below = kInf);
  // The state-independent part of join_bound (plan/chain_join.cpp).
  void build_join();
  // join_set_bound for things at `a` (-1: unknown), then forced by guards g1 and gk.
  double join_between(const std::vector<int>& a, std::uint32_t g1, std::uint32_t gk) const;

  struct Step {
    std::uint32_t src, dst;
    int forcing;     // index into cubes_, or -1
    bool accepting;  // Automaton::accepting_edge (state-based: dst is accepting)
  };
  // A walk starting at q has passed acceptance already (state-based: q is
  // accepting; transition-based: never, acceptance is on the steps).
  bool starts_accepted(std::uint32_t q) const { return !transition_based_ && accepting_[q]; }
  const task::System* ts_ = nullptr;
  const MotionCostModel* model_ = nullptr;
  std::vector<Step> steps_;                // the useful automaton edges that can hold
  std::vector<std::vector<int>> forced_;   // per forcing cube: location per thing, -1 free
  bool enabled_ = false;
  std::uint32_t n_states_ = 0, n_forcing_ = 0;
  std::vector<automata::Cube> cubes_;
  std::vector<double> d_;                   // D(i, j) at i * n_forcing_ + j
  std::vector<std::vector<Arc>> arcs_;      // per node of G
  // State-based: the accepting states; transition-based: the states an
  // accepting step enters (every accepting cycle passes one). kappa is kept
  // for these.
  std::vector<bool> accepting_;
  bool transition_based_ = false;
  // per automaton state; kInf: no cycle through it (transition-based: no
  // closed walk through it that ends with an accepting step)
  std::vector<double> kappa_;
  double min_kappa_ = 0;                     // over the accepting states
  std::vector<double> zero_tail_;           // per automaton state
  struct Tail {
    double path, kappa;
  };
  std::vector<std::vector<std::pair<std::uint32_t, Tail>>> entries_;  // per state: (forcing c, tail(c))
  // join_bound's tables, per automaton state q: the prefix's first forcing
  // guard c with the least rest of the bound after it; the (first, last)
  // forcing guards of accepting cycles through a state reached from q
  // without one, by their least chain between; whether such a cycle reads none.
  std::vector<std::vector<std::pair<std::uint32_t, double>>> join_first_;
  struct JoinPair {
    std::uint32_t g1, gk;
    double cycle;
  };
  std::vector<std::vector<JoinPair>> join_pairs_;  // ascending cycle
  std::vector<std::uint8_t> join_free_;
  std::vector<double> dist_;                // Dijkstra work space
  std::vector<std::uint8_t> done_;
};

}  // namespace rtamp::plan
