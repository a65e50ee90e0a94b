// Motion-cost models: the edge weight w of the paper's Section III.B (the
// "skill library" the planner asks for the cost of an action). The search
// calls a model per product edge; the robot layer implements an inverse-
// kinematics model ("ik") against this same interface.
//
// What a cost may depend on is exactly a MotionQuery: the thing moved (its
// stable id, class and whether it is a container), the hand's point before
// the action, the thing's point, and the destination's point (points are
// defined in task/transition_system.hpp: centres of locations; the hand starts
// at the robot's home point, base + (0, 0, 0.5 m)). The motion-cost cache
// (motion_cost_cache.hpp) keys on the query, masked by depends(), so a model
// must not read anything else. `stay` always costs 0 and is never asked.
//
// Built-in models, for move(o, l) with the hand at point h, o at point p and
// l at point t (Euclidean norms |.|, metres):
//   euclid : |h - p| + |p - t|   (the hand travels to o, then carries it to l)
//   region : |p - t|             (centre to centre, hand ignored; the usual
//                                  edge weight of LTL planners)
//   unit   : 1
// Example (euclid): hand at home (0, 0, 0.5), o in r1 centred at (0.4, 0, 0),
// l = r2 centred at (0.4, 0.5, 0): cost = sqrt(0.16 + 0.25) + 0.5 = 1.1403 m.
//
// transport_bound(t) bounds from below the cost of any action sequence after
// which at least t.m of the things at points t.from[0..n) have each been put
// at the destination by a move of their own (the heuristics use it for
// "all/any/count C in L"). The default is the m-th smallest single
// lower_bound, valid for every model; the built-in models override it with
// sharper bounds that hold when every move carries exactly one thing
// (t.one_at_a_time: the system has no containers) — see docs/planning.md.
//
// lower_bound(q) must be a lower bound on the total cost of ANY sequence of
// actions that starts with the hand at q.hand, picks up the thing that is at
// q.from (the thing itself or a container holding it) and finally brings it
// to q.to (q.to may be "anywhere": kAnywhere). The A* heuristics combine these
// per-thing bounds with max/min only, so they stay admissible and consistent
// as long as lower_bound is consistent (h(q) <= c(a) + h(q') for every action
// a); returning 0 is always correct.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "rtamp/task/transition_system.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::plan {

struct MotionQuery {
  std::uint64_t thing = 0;   // stable id of the moved thing (task::System::thing_uid)
  bool container = false;    // the moved thing is a container
  world::Vec3 hand{};        // hand point before the action
  world::Vec3 from{};        // the thing's point
  world::Vec3 to{};          // the destination's point
};

// Which fields of a MotionQuery a model's cost depends on (bit set).
enum Depends : unsigned {
  kDependsThing = 1,
  kDependsHand = 2,
  kDependsFrom = 4,
  kDependsTo = 8,
  kDependsAll = 15,
};

inline double distance(const world::Vec3& a, const world::Vec3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

struct TransportQuery {
  world::Vec3 hand{};
  const world::Vec3* from = nullptr;  // current points of the candidate things
  std::size_t n = 0;                  // number of candidates
  std::size_t m = 0;                  // how many of them must arrive (1 <= m <= n)
  bool to_known = false;              // the destination is a region at `to` (else a container)
  world::Vec3 to{};
  bool one_at_a_time = false;         // no containers: each move carries exactly one thing
  double nearest = 0;                 // distance from `to` to the nearest other location point
  std::vector<double>* scratch = nullptr;  // work space (n entries), owned by the caller
};

// One thing of MotionCostModel::join_set_bound: its points a, b, c, each
// known or not (an unknown one constrains nothing).
struct JoinPoints {
  world::Vec3 a{}, b{}, c{};
  bool has_a = false, has_b = false, has_c = false;
};

// Sum of the k smallest values of v (reorders v).
double sum_smallest(std::vector<double>& v, std::size_t k);
// k-th smallest value of v, 1-based (reorders v); +inf if v has fewer.
double kth_smallest(std::vector<double>& v, std::size_t k);

class MotionCostModel {
 public:
  virtual ~MotionCostModel() = default;
  virtual std::string name() const = 0;
  // Cost of moving q.thing from q.from to q.to with the hand at q.hand: >= 0,
  // or +infinity for a move the model cannot do (it gets no product edge). NaN
  // or negative is an error (plan/cost_check.hpp; so is a bound below that is
  // NaN, infinite or negative).
  virtual double cost(const MotionQuery& q) const = 0;
  // See the header comment. `to_anywhere`: the destination is not known.
  virtual double lower_bound(const MotionQuery& q, bool to_anywhere) const = 0;
  // Which MotionQuery fields cost() reads (Depends bits).
  virtual unsigned depends() const = 0;
  virtual double transport_bound(const TransportQuery& t) const;
  // Lower bound on the total cost of the moves of one thing, each carrying
  // only that thing, that take it from point `from` to point `to`, wherever
  // the hand is (plan/chain_bound.hpp sums these over things). 0 is always
  // correct.
  virtual double carry_bound(const world::Vec3& /*from*/, const world::Vec3& /*to*/) const { return 0; }
  // Lower bound on the total cost of moves, each carrying one thing, after
  // which thing i has gone from from[i] to to[i] (i < n), wherever the hand
  // starts and whatever detours the things take (plan/chain_bound.hpp). The
  // sum of carry_bound is always correct (and the default).
  virtual double carry_set_bound(const world::Vec3* from, const world::Vec3* to, std::size_t n) const;
  // Lower bound on the total cost of two disjoint stretches of moves, each
  // move carrying one thing: in the first, thing i goes from p[i].a to some
  // place J_i and on to p[i].b; in the second, from p[i].c to the same J_i;
  // any J (plan/chain_bound.hpp: the stretch through a lasso's join and its
  // cycle's last one). The default: the sum over things of
  // max(carry_bound(a, b), carry_bound(c, b)) (a -> J -> b, and c -> J with
  // J -> b, each move the thing from one point to the other).
  virtual double join_set_bound(const JoinPoints* p, std::size_t n) const;
  // Costs of this model are expensive enough to be worth caching (the
  // planner's experience cache is used only then). Models are assumed
  // expensive unless they say otherwise; the closed-form ones below are
  // cheaper to compute than to look up.
  virtual bool expensive() const { return true; }

  // The query for `a` in state `s` of `ts` (a must be a move).
  static MotionQuery query(const task::System& ts, const task::State& s, const task::Action& a);
  // cost(s, a): 0 for stay, else cost(query(ts, s, a)).
  double cost(const task::System& ts, const task::State& s, const task::Action& a) const {
    return a.is_stay() ? 0.0 : cost(query(ts, s, a));
  }
};

class EuclidCost final : public MotionCostModel {
 public:
  std::string name() const override { return "euclid"; }
  double cost(const MotionQuery& q) const override { return distance(q.hand, q.from) + distance(q.from, q.to); }
  double lower_bound(const MotionQuery& q, bool to_anywhere) const override {
    return distance(q.hand, q.from) + (to_anywhere ? 0.0 : distance(q.from, q.to));
  }
  unsigned depends() const override { return kDependsHand | kDependsFrom | kDependsTo; }
  bool expensive() const override { return false; }
  double transport_bound(const TransportQuery& t) const override;
  // Each move adds |p - t| for the thing's own stretch (triangle inequality).
  double carry_bound(const world::Vec3& from, const world::Vec3& to) const override { return distance(from, to); }
  // The hand's path, projected on an axis, crosses each point x at least
  // max(F + B, 2 max(F, B) - 1) times, F (B) the things that must pass x
  // forward (backward): the integral over x, on the moves' own directions
  // (docs/planning.md, "The hand's way back").
  double carry_set_bound(const world::Vec3* from, const world::Vec3* to, std::size_t n) const override;
  // The same count of crossings, for each stretch, minimised over the side
  // of x each J_i lies on (docs/planning.md, "The join's stretch").
  double join_set_bound(const JoinPoints* p, std::size_t n) const override;
};

class RegionCost final : public MotionCostModel {
 public:
  std::string name() const override { return "region"; }
  double cost(const MotionQuery& q) const override { return distance(q.from, q.to); }
  double lower_bound(const MotionQuery& q, bool to_anywhere) const override {
    return to_anywhere ? 0.0 : distance(q.from, q.to);
  }
  unsigned depends() const override { return kDependsFrom | kDependsTo; }
  bool expensive() const override { return false; }
  double transport_bound(const TransportQuery& t) const override;
  double carry_bound(const world::Vec3& from, const world::Vec3& to) const override { return distance(from, to); }
};

class UnitCost final : public MotionCostModel {
 public:
  std::string name() const override { return "unit"; }
  double cost(const MotionQuery&) const override { return 1.0; }
  // Any sequence that must pick the thing contains at least one move.
  double lower_bound(const MotionQuery&, bool) const override { return 1.0; }
  unsigned depends() const override { return 0; }
  bool expensive() const override { return false; }
  // Every one of the m things needs a move of its own.
  double transport_bound(const TransportQuery& t) const override { return double(t.m); }
  // A thing that changes place needs at least one move (callers pass distinct places).
  double carry_bound(const world::Vec3&, const world::Vec3&) const override { return 1.0; }
};

// Models by name (euclid, region, unit, and those other layers register): plan/registry.hpp.

}  // namespace rtamp::plan
