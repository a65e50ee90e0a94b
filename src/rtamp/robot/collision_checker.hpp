// The collision-checking interface the skills plan against. The robot layer never
// calls MuJoCo: the sim layer implements this with MuJoCo's collision detection on
// a scratch copy of the world (docs/design.md, "Collision-aware motion"); tests use
// synthetic checkers. Segments are checked by dense sampling.
// Invariant: config_collides is a pure function of q for the checker's lifetime
// (the world it checks against does not change while a plan is being made).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

#include "rtamp/robot/joints.hpp"

namespace rtamp::robot {

class CollisionChecker {
 public:
  virtual ~CollisionChecker() = default;
  // True if the arm (and whatever it holds) at q penetrates the table, objects, containers or itself.
  virtual bool config_collides(const Joints& q) = 0;
};

// A checker from a function (tests, quick experiments).
class FunctionCollisionChecker final : public CollisionChecker {
 public:
  explicit FunctionCollisionChecker(std::function<bool(const Joints&)> f) : f_(std::move(f)) {}
  bool config_collides(const Joints& q) override {
    ++calls_;
    return f_(q);
  }
  long calls() const { return calls_; }

 private:
  std::function<bool(const Joints&)> f_;
  long calls_ = 0;
};

// True if any configuration on the straight joint segment a→b collides, sampled so that
// no joint moves more than `resolution` radians between checks (both ends included).
inline bool segment_collides(CollisionChecker& checker, const Joints& a, const Joints& b, double resolution = 0.02) {
  const int n = std::max(1, static_cast<int>(std::ceil(max_joint_delta(a, b) / resolution)));
  for (int k = 0; k <= n; ++k) {
    Joints q;
    const double f = static_cast<double>(k) / n;
    for (std::size_t j = 0; j < kDof; ++j) q[j] = a[j] + f * (b[j] - a[j]);
    if (checker.config_collides(q)) return true;
  }
  return false;
}

}  // namespace rtamp::robot
