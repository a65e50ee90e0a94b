// Heuristics for the product search, separate from the search algorithm
// (Fast Downward style: A* = best-first search + a heuristic; Dijkstra = the
// same search with ZeroHeuristic).
//
// GuardHeuristic, h(s, q), a lower bound on the cost from (s, q) to an
// accepting product node (transition-based automata: to taking an accepting
// edge, whose walk ends with that edge and reads its guard too):
//   0 if q is accepting; otherwise every path to acceptance follows some walk
//   q -> q1 -> ... -> qk (qk accepting, all useful) of the BA, each of whose
//   guards holds in the label of a TS state on the way, so the path costs at
//   least the largest LB(s, guard) of its walk, and
//   h(s, q) = min over those walks of max over their guards of LB(s, guard)
//   (a minimax path over the BA states, `walk`; when every exit of q enters
//   an accepting state it is the cheapest exit), with
//   LB(s, cube) = max over the cube's literals of LB(s, literal).
//   The same walk bound towards one BA state (walk_bound) bounds the cycle
//   search's way back to an accepting node.
//   Without containers, h is also at least ChainBound's sum of the motion
//   between the locations the guards force, plus the least such sum around an
//   accepting cycle (plan/chain_bound.hpp) — a bound on the whole lasso.
// LB(s, proposition wanted true/false) walks the compiled PropExpr: And takes
// the max (every conjunct must hold), Or the min, Not flips the wanted value;
// an atom that already has the wanted value costs 0; otherwise the things that
// must change location are known (`o in L`: o; `all C in L`: every C not in L;
// `any`: one of them; `count`: the k cheapest), and each contributes the cost
// model's lower_bound for "the hand reaches the thing, which then reaches L"
// (motion_cost.hpp); several things that must all (or k of them) arrive
// combine by the model's transport_bound: at least the k-th smallest single
// bound, and for systems without containers (every move carries one thing)
// sums of carried distances and return trips (motion_cost.cpp, docs/planning.md).
// Unsatisfiable literals give +inf (the node is pruned).
// Why not "BA distance to acceptance x cheapest action": stay costs 0 and can
// advance the BA, so that product is 0; the guard bound is never weaker.
// Admissible by the arguments above; consistent when lower_bound is (the
// search re-opens nodes anyway, so admissibility is all optimality needs).
//
// ExperienceHeuristic = max(GuardHeuristic, the learned bounds of the
// graph's experience, plan/experience.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rtamp/plan/chain_bound.hpp"
#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/product_graph.hpp"

namespace rtamp::plan {

class Heuristic {
 public:
  virtual ~Heuristic() = default;
  virtual std::string name() const = 0;
  // Lower bound on the cost of the best lasso continuing from node n.
  virtual double estimate(const ProductGraph& g, NodeId n) = 0;
  // Lower bound on the cost of a path of at least one step from node n to a
  // node whose automaton state is `target` (the cycle search's way back to
  // an accepting node). 0 is always correct.
  virtual double walk_bound(const ProductGraph&, NodeId, std::uint32_t /*target*/) { return 0; }
  // Lower bound on the cost of every cycle (>= 1 step) through node n that
  // takes an accepting edge (passes an accepting node; the cycle of a lasso
  // joined at n). 0 is always correct.
  virtual double cycle_bound(const ProductGraph&, NodeId) { return 0; }
  // Lower bound on the cost of a path of at least one step from node n to
  // node `target` that takes an accepting edge unless `accepted` (the rest
  // of a cycle search's cycle back to its join node). 0 is always correct.
  virtual double return_bound(const ProductGraph&, NodeId, NodeId /*target*/, bool /*accepted*/) { return 0; }
};

class ZeroHeuristic final : public Heuristic {
 public:
  std::string name() const override { return "zero"; }
  double estimate(const ProductGraph&, NodeId) override { return 0; }
};

class GuardHeuristic : public Heuristic {
 public:
  explicit GuardHeuristic(const ProductGraph& g);
  std::string name() const override { return "guard"; }
  double estimate(const ProductGraph& g, NodeId n) override { return evaluate(g.state(n), g.ba_state(n)); }
  double walk_bound(const ProductGraph& g, NodeId n, std::uint32_t target) override {
    return walk(g.state(n), g.ba_state(n), target);
  }
  // The chain bound's cycle bound at n (0 without it).
  double cycle_bound(const ProductGraph& g, NodeId n) override {
    return chain_ ? std::max(chain_->cycle_bound(), chain_->cycle_bound_at(g.state(n), g.ba_state(n))) : 0.0;
  }
  // The chain bound's path bound from n to target (0 without it).
  double return_bound(const ProductGraph& g, NodeId n, NodeId target, bool accepted) override {
    return chain_ ? chain_->path_bound(g.state(n), g.ba_state(n), g.state(target), g.ba_state(target), accepted)
                  : 0.0;
  }
  // Every automaton walk q = q0 -> q1 -> ... -> qk = target (k >= 1, self-loops
  // included) reads each guard in some TS state on the way, so a path along it
  // costs at least the largest LB(s, guard); walk() is the smallest such
  // largest value over all walks (a minimax path over the useful states).
  // target = kAnyAccepting: the walk may end in any accepting state, or
  // (transition-based) with any accepting edge.
  static constexpr std::uint32_t kAnyAccepting = ~std::uint32_t{0};
  double walk(const task::State& s, std::uint32_t q, std::uint32_t target);
  double evaluate(const task::State& s, std::uint32_t q);
  // LB(s, proposition node wanted `want`) — exposed for tests.
  double literal_bound(const task::State& s, std::uint32_t node, bool want);

 private:
  double bound_in(const task::State& s, unsigned thing, int loc);  // thing must end up directly in loc
  double bound_out(const task::State& s, unsigned thing);         // thing must leave its location
  // Bound for m of the candidate things (current points in points_[depth_]) to be moved into
  // `loc` (into = true) or out of their location (into = false). `s` and `members` (the
  // class the candidates were taken from) only name a thing in the error for a bad value.
  double transport(std::size_t m, int loc, bool into, const task::State& s, const std::vector<unsigned>& members);

  const task::System* ts_;
  const task::Labeling* lab_;
  const automata::Automaton* ba_;
  const MotionCostModel* model_;
  std::vector<bool> accepting_;
  std::vector<std::vector<automata::Cube>> exits_;  // per BA state: guards of the edges to other useful states
  std::vector<bool> direct_;  // every exit of the state enters an accepting state (walk = cheapest exit)
  // walk(): the useful edges (self-loops included) per BA state, and a step
  // into the sink (index num_states()) per accepting edge of a
  // transition-based automaton; literal bounds computed at most once per call
  // (stamped), minimax distances.
  std::vector<std::vector<std::pair<std::uint32_t, automata::Cube>>> steps_;
  std::vector<double> literal_;
  std::vector<std::uint32_t> literal_stamp_;
  std::uint32_t call_ = 0;
  std::vector<double> walk_d_;
  std::vector<std::uint8_t> walk_done_;
  double cube_bound(const task::State& s, const automata::Cube& cube);
  void begin_call(const task::State& s);  // new literal-cache stamp, hand point of s
  double walk_from(const task::State& s, std::uint32_t q, std::uint32_t target);  // walk() after begin_call
  std::unique_ptr<ChainBound> chain_;  // null when it cannot help
  std::vector<double> chain_first_;
  std::vector<bool> useful_;
  std::vector<std::vector<double>> scratch_;  // per recursion depth
  std::vector<std::vector<world::Vec3>> points_;  // per recursion depth
  std::vector<double> nearest_;  // per region: distance to the nearest other region centre
  unsigned depth_ = 0;
  world::Vec3 hand_{};
};

class ExperienceHeuristic final : public Heuristic {
 public:
  // `x` must be the experience of `g` and outlive the heuristic.
  ExperienceHeuristic(const ProductGraph& g, Experience& x) : guard_(g), x_(&x) {}
  std::string name() const override { return "guard+experience"; }
  // The guard bound is cached per node in the experience (it does not depend
  // on the start), so replans on the same graph never recompute it.
  double walk_bound(const ProductGraph& g, NodeId n, std::uint32_t target) override {
    return guard_.walk_bound(g, n, target);
  }
  double cycle_bound(const ProductGraph& g, NodeId n) override { return guard_.cycle_bound(g, n); }
  double return_bound(const ProductGraph& g, NodeId n, NodeId target, bool accepted) override {
    return guard_.return_bound(g, n, target, accepted);
  }
  double estimate(const ProductGraph& g, NodeId n) override {
    double h = x_->cached_h(n);
    if (h < 0) {
      h = guard_.estimate(g, n);
      x_->cache_h(n, h);
    }
    const double l = x_->learned(n);
    return h > l ? h : l;
  }

 private:
  GuardHeuristic guard_;
  Experience* x_;
};

// Lower bound on the cost of going from state s to exactly the state `target`
// (for the cycle search back to an accepting node): the max over things whose
// location differs of the model's lower_bound (thing -> its target location);
// +inf if the target has the hand at home and s does not (the hand is at home
// only before the first move, so such a target is never reached again).
// Interchangeable objects (task::System::set_symmetry) count by group: in
// canonical states a member's target may be reached by a twin, so where the
// target has k more members of a group in a region than s, the bound is the
// model's transport_bound for k of the members elsewhere to arrive there.
// Interchangeable containers (set_container_symmetry) are skipped, and so are
// things in interchangeable containers in both states (their container's name
// may permute).
double state_distance_bound(const task::System& ts, const MotionCostModel& model, const task::State& s,
                            const task::State& target);

}  // namespace rtamp::plan
