// Joint vectors of a 6-axis arm, joint limits, angle wrapping and the weighted
// joint distance used to pick "the solution nearest the current configuration"
// (docs/design.md robot layer; the paper's skill library moves a UR5 in joint space).
//
// Invariants: a JointLimits has lower[j] <= upper[j] for every joint; wrap_joint
// returns an angle equivalent (mod 2π) to its input and inside [lower, upper]
// (never NaN), choosing among the equivalent angles the one nearest `near`.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rtamp::robot {

inline constexpr int kDof = 6;
using Joints = std::array<double, kDof>;

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct JointLimits {
  Joints lower{-kTwoPi, -kTwoPi, -kTwoPi, -kTwoPi, -kTwoPi, -kTwoPi};
  Joints upper{kTwoPi, kTwoPi, kTwoPi, kTwoPi, kTwoPi, kTwoPi};

  // The UR5's own limits: ±2π on every joint but the elbow (joint 3), which is ±π
  // (Universal Robots' description; the values are read from models/ur5.xml at build
  // time, defined in ur5_kinematics.cpp).
  static JointLimits ur5();

  bool contains(const Joints& q, double tol = 1e-12) const {
    for (int j = 0; j < kDof; ++j)
      if (!(q[j] >= lower[j] - tol && q[j] <= upper[j] + tol)) return false;
    return true;
  }

  // The angle equivalent to `angle` (angle + 2πk) inside [lower[j], upper[j]]
  // that is nearest `near`. False when no equivalent angle is inside the limits.
  bool wrap_joint(int j, double angle, double near, double& out) const {
    if (!std::isfinite(angle)) return false;
    constexpr double eps = 1e-9;
    const double kmin = std::ceil((lower[j] - angle) / kTwoPi - eps);
    const double kmax = std::floor((upper[j] - angle) / kTwoPi + eps);
    if (kmin > kmax) return false;
    double k = std::isfinite(near) ? std::round((near - angle) / kTwoPi) : std::round(-angle / kTwoPi);
    if (k < kmin) k = kmin;
    if (k > kmax) k = kmax;
    double v = angle + k * kTwoPi;
    // Rounding may leave v a hair outside: clamp (it is then within eps of the limit).
    if (v < lower[j]) v = lower[j];
    if (v > upper[j]) v = upper[j];
    out = v;
    return true;
  }

  // Wraps every joint of q in place (see wrap_joint). False (q unspecified) if any fails.
  bool wrap(Joints& q, const Joints& near) const {
    for (int j = 0; j < kDof; ++j)
      if (!wrap_joint(j, q[j], near[j], q[j])) return false;
    return true;
  }
};

// Default weights of the joint distance: the three big joints count more than the wrist.
inline constexpr Joints kDefaultJointWeights{1.0, 1.0, 1.0, 0.5, 0.5, 0.5};

// sqrt(Σ w_j (a_j − b_j)²). Separable, so choosing each joint's 2π-representative
// nearest b minimises it joint by joint.
inline double weighted_distance(const Joints& a, const Joints& b, const Joints& w = kDefaultJointWeights) {
  double s = 0;
  for (int j = 0; j < kDof; ++j) s += w[j] * (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(s);
}

// Largest |a_j − b_j|.
inline double max_joint_delta(const Joints& a, const Joints& b) {
  double m = 0;
  for (int j = 0; j < kDof; ++j) m = std::max(m, std::abs(a[j] - b[j]));
  return m;
}

// |a − b| mod 2π folded to [0, π] on every joint; the largest of them.
inline double max_angle_difference(const Joints& a, const Joints& b) {
  double m = 0;
  for (int j = 0; j < kDof; ++j) {
    const double x = a[j] - b[j];
    const double d = x - kTwoPi * std::nearbyint(x / kTwoPi);  // std::remainder, but fast
    m = std::max(m, std::abs(d));
  }
  return m;
}

}  // namespace rtamp::robot
