// UR5 kinematics: FK against an independently written product-of-exponentials
// model (the screw axes of Lynch & Park, "Modern Robotics", Example 4.5, whose
// base frame is the DH base turned by π about z), and FK∘IK round trips.
#include "rtamp/robot/ur5_kinematics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace rtamp::robot {
namespace {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

Matrix3d skew(const Vector3d& w) {
  Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

// exp([S] θ) for a screw S = (ω, v) with |ω| = 1.
Isometry3d screw_exp(const Vector3d& w, const Vector3d& v, double th) {
  const Matrix3d W = skew(w);
  const Matrix3d R = Matrix3d::Identity() + std::sin(th) * W + (1 - std::cos(th)) * W * W;
  const Vector3d p = (Matrix3d::Identity() * th + (1 - std::cos(th)) * W + (th - std::sin(th)) * W * W) * v;
  Isometry3d t = Isometry3d::Identity();
  t.linear() = R;
  t.translation() = p;
  return t;
}

// Space-frame PoE of the UR5 (Modern Robotics Example 4.5) with the UR5's
// DH dimensions: W1 = d4, W2 = d6, L1 = |a2|, L2 = |a3|, H1 = d1, H2 = d5.
Isometry3d poe_flange(const Joints& q) {
  const double W1 = 0.10915, W2 = 0.0823, L1 = 0.425, L2 = 0.39225, H1 = 0.089159, H2 = 0.09465;
  const Vector3d w[6] = {{0, 0, 1}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 1, 0}};
  const Vector3d v[6] = {{0, 0, 0},       {-H1, 0, 0},        {-H1, 0, L1},
                         {-H1, 0, L1 + L2}, {-W1, L1 + L2, 0}, {H2 - H1, 0, L1 + L2}};
  Isometry3d M = Isometry3d::Identity();
  M.matrix().block<3, 3>(0, 0) << -1, 0, 0, 0, 0, 1, 0, 1, 0;
  M.translation() = Vector3d(L1 + L2, W1 + W2, H1 - H2);
  Isometry3d t = Isometry3d::Identity();
  for (int i = 0; i < 6; ++i) t = t * screw_exp(w[i], v[i], q[static_cast<std::size_t>(i)]);
  t = t * M;
  // MR's base is the DH base turned by π about z.
  Isometry3d rz = Isometry3d::Identity();
  rz.linear() = Eigen::AngleAxisd(std::numbers::pi, Vector3d::UnitZ()).toRotationMatrix();
  return rz.inverse() * t;
}

Joints random_joints(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  Joints q;
  for (double& x : q) x = u(rng);
  return q;
}

bool all_finite(const Joints& q) {
  for (double x : q)
    if (!std::isfinite(x)) return false;
  return true;
}

TEST(Ur5Kinematics, ZeroConfigurationMatchesHandDerivedGeometry) {
  Ur5Kinematics k;
  const Isometry3d f = k.flange_pose(Joints{});
  // Arm stretched along −x of the base: flange at (a2 + a3, −d4 − d6, d1 − d5), tool z along −y.
  EXPECT_NEAR(f.translation().x(), -0.425 - 0.39225, 1e-12);
  EXPECT_NEAR(f.translation().y(), -0.10915 - 0.0823, 1e-12);
  EXPECT_NEAR(f.translation().z(), 0.089159 - 0.09465, 1e-12);
  EXPECT_TRUE(f.linear().col(2).isApprox(Vector3d(0, -1, 0), 1e-12));
  EXPECT_TRUE(f.linear().col(0).isApprox(Vector3d(1, 0, 0), 1e-12));
}

TEST(Ur5Kinematics, FkAgreesWithProductOfExponentials) {
  Ur5Kinematics k;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const Joints q = random_joints(rng, -2 * std::numbers::pi, 2 * std::numbers::pi);
    const Isometry3d a = k.flange_pose(q), b = poe_flange(q);
    ASSERT_LT(position_error(a, b), 1e-12) << i;
    ASSERT_LT(rotation_error(a, b), 1e-12) << i;
  }
}

TEST(Ur5Kinematics, LinkFramesChainToFlangeAndToolIsOffsetAlongZ) {
  Ur5Kinematics::Config c;
  c.tool_offset = 0.2;
  c.base = Ur5Kinematics::base_pose(world::Robot{"ur5", {0.3, -0.2, 0.1}, 0.7});
  Ur5Kinematics k(c);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 100; ++i) {
    const Joints q = random_joints(rng, -3, 3);
    const auto frames = k.link_frames(q);
    EXPECT_TRUE(frames[0].isApprox(c.base, 1e-14));
    EXPECT_LT(position_error(frames[6], k.flange_pose(q)), 1e-14);
    const Isometry3d t = k.tool_pose(q);
    EXPECT_NEAR((t.translation() - frames[6].translation()).norm(), 0.2, 1e-12);
    EXPECT_NEAR((t.translation() - frames[6].translation()).dot(frames[6].linear().col(2)), 0.2, 1e-12);
    EXPECT_LT((k.tool_point(q) - t.translation()).norm(), 1e-14);
    // Base placement: the world pose is base * (pose of the unplaced robot).
    Ur5Kinematics unplaced(Ur5Kinematics::Config{c.dh, 0.2, c.limits, Isometry3d::Identity()});
    EXPECT_LT(position_error(c.base * unplaced.tool_pose(q), t), 1e-12);
  }
}

void check_round_trip(const Ur5Kinematics& k, const Joints& q, bool expect_generator, int* n_solutions = nullptr) {
  const Isometry3d target = k.tool_pose(q);
  IkSolutions sols;
  k.ik_tool(target, sols);
  if (n_solutions) *n_solutions = sols.count;
  ASSERT_GE(sols.count, 1) << "no IK solution for a pose produced by FK";
  ASSERT_LE(sols.count, 8);
  bool found = false;
  for (const Joints& s : sols) {
    ASSERT_TRUE(all_finite(s));
    ASSERT_TRUE(k.limits().contains(s));
    const Isometry3d got = k.tool_pose(s);
    ASSERT_LT(position_error(got, target), 1e-6);
    ASSERT_LT(rotation_error(got, target), 1e-6);
    if (max_angle_difference(s, q) < 1e-6) found = true;
  }
  for (int a = 0; a < sols.count; ++a)
    for (int b = a + 1; b < sols.count; ++b) ASSERT_GT(max_angle_difference(sols[a], sols[b]), 1e-9);
  if (expect_generator) {
    ASSERT_TRUE(found) << "generating configuration not among the solutions";
  }
}

TEST(Ur5Kinematics, IkRoundTripOnRandomReachablePoses) {
  Ur5Kinematics::Config c;
  c.base = Ur5Kinematics::base_pose(world::Robot{"ur5", {0.1, 0.2, 0.0}, -1.1});
  Ur5Kinematics k(c);
  std::mt19937_64 rng(42);
  const int n = 5000;
  for (int i = 0; i < n; ++i) {
    const Joints q = random_joints(rng, -2 * std::numbers::pi, 2 * std::numbers::pi);
    ASSERT_NO_FATAL_FAILURE(check_round_trip(k, q, true)) << i;
  }
}

// Completeness oracle: damped least squares (numerical Jacobian of FK, no IK code
// shared) from many random starts; every configuration it converges to must be one
// of the analytic solutions (mod 2π).
TEST(Ur5Kinematics, IkFindsEverySolutionANumericalSolverFinds) {
  Ur5Kinematics k;
  std::mt19937_64 rng(21);
  auto pose_error = [&](const Joints& q, const Isometry3d& target) {
    const Isometry3d f = k.flange_pose(q);
    Eigen::Matrix<double, 6, 1> e;
    e.head<3>() = target.translation() - f.translation();
    const Eigen::AngleAxisd aa(target.linear() * f.linear().transpose());
    e.tail<3>() = aa.angle() * aa.axis();
    return e;
  };
  // Under the sanitizers (about 10x slower) 40 poses; the Release run checks 150.
  const int poses = RTAMP_SANITIZER_BUILD ? 40 : 150;
  int converged = 0;
  for (int i = 0; i < poses; ++i) {
    const Joints q = random_joints(rng, -std::numbers::pi, std::numbers::pi);
    const Isometry3d target = k.flange_pose(q);
    IkSolutions sols;
    k.ik_flange(target, sols);
    for (int start = 0; start < 25; ++start) {
      Joints x = random_joints(rng, -std::numbers::pi, std::numbers::pi);
      for (int it = 0; it < 200; ++it) {
        const auto e = pose_error(x, target);
        if (e.norm() < 1e-11) break;
        Eigen::Matrix<double, 6, 6> J;
        for (int j = 0; j < 6; ++j) {
          Joints xp = x;
          xp[static_cast<std::size_t>(j)] += 1e-7;
          J.col(j) = -(pose_error(xp, target) - e) / 1e-7;
        }
        const Eigen::Matrix<double, 6, 1> dx =
            J.transpose() * (J * J.transpose() + 1e-6 * Eigen::Matrix<double, 6, 6>::Identity()).ldlt().solve(e);
        for (int j = 0; j < 6; ++j) x[static_cast<std::size_t>(j)] += std::clamp(dx(j), -0.3, 0.3);
      }
      if (pose_error(x, target).norm() > 1e-9) continue;
      ++converged;
      double best = 1e9;
      for (const Joints& s : sols) best = std::min(best, max_angle_difference(s, x));
      ASSERT_LT(best, 1e-5) << "numerical IK found a solution the closed form missed (pose " << i << ")";
    }
  }
  EXPECT_GT(converged, poses * 10 / 3);
}

TEST(Ur5Kinematics, IkWithTighterLimitsStaysInside) {
  Ur5Kinematics::Config c;
  for (int j = 0; j < kDof; ++j) {
    c.limits.lower[static_cast<std::size_t>(j)] = -std::numbers::pi;
    c.limits.upper[static_cast<std::size_t>(j)] = std::numbers::pi;
  }
  c.limits.lower[1] = -std::numbers::pi;  // shoulder: only upward half
  c.limits.upper[1] = 0;
  Ur5Kinematics k(c);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 2000; ++i) {
    Joints q = random_joints(rng, -std::numbers::pi, std::numbers::pi);
    q[1] = std::uniform_real_distribution<double>(-std::numbers::pi, 0)(rng);
    ASSERT_NO_FATAL_FAILURE(check_round_trip(k, q, true));
  }
}

TEST(Ur5Kinematics, SingularConfigurationsGiveFiniteValidSolutions) {
  Ur5Kinematics k;
  std::mt19937_64 rng(11);
  const double pi = std::numbers::pi;
  for (int i = 0; i < 500; ++i) {
    Joints q = random_joints(rng, -pi, pi);
    // Wrist singular (θ5 = 0, π and nearly so), elbow straight / folded, and both.
    const double wrist[] = {0.0, pi, 1e-9, -1e-12, pi - 1e-10, 1e-6};
    for (double t5 : wrist) {
      Joints s = q;
      s[4] = t5;
      ASSERT_NO_FATAL_FAILURE(check_round_trip(k, s, false));
    }
    {
      // Exactly wrist-singular: with the generator as reference (θ6 kept), it is found again.
      Joints s = q;
      s[4] = 0;
      IkSolutions sols;
      k.ik_tool(k.tool_pose(s), sols, &s);
      double best = 1e9;
      for (const Joints& x : sols) best = std::min(best, max_angle_difference(x, s));
      ASSERT_LT(best, 1e-6);
    }
    const double elbow[] = {0.0, 1e-10, -1e-7};
    for (double t3 : elbow) {
      Joints s = q;
      s[2] = t3;
      ASSERT_NO_FATAL_FAILURE(check_round_trip(k, s, false));
      s[4] = 0;
      ASSERT_NO_FATAL_FAILURE(check_round_trip(k, s, false));
    }
  }
}

TEST(Ur5Kinematics, ShoulderSingularityWristCentreAtDistanceD4) {
  // Solve for θ2, θ3 that put the wrist centre at horizontal distance exactly d4 from
  // joint 1's axis: then the two shoulder branches coincide.
  Ur5Kinematics k;
  const double pi = std::numbers::pi;
  // With θ2 = −π/2 (upper arm vertical), θ3 = 0 and θ4 = −π/2, θ5 = π/2 ... search numerically.
  std::mt19937_64 rng(9);
  int tested = 0;
  for (int i = 0; i < 20000 && tested < 50; ++i) {
    Joints q = random_joints(rng, -pi, pi);
    const Isometry3d f = k.flange_pose(q);
    const Vector3d p5 = f.translation() - 0.0823 * f.linear().col(2);
    if (std::abs(std::hypot(p5.x(), p5.y()) - 0.10915) > 0.02) continue;
    ++tested;
    ASSERT_NO_FATAL_FAILURE(check_round_trip(k, q, true));
  }
  EXPECT_GT(tested, 0);
}

TEST(Ur5Kinematics, UnreachablePosesHaveNoSolutionAndNoNaN) {
  Ur5Kinematics k;
  IkSolutions sols;
  Isometry3d far = Isometry3d::Identity();
  far.translation() = Vector3d(2.0, 0, 0.3);
  EXPECT_EQ(k.ik_tool(far, sols), 0);
  Isometry3d onaxis = Isometry3d::Identity();  // flange right on joint 1's axis
  EXPECT_EQ(k.ik_flange(onaxis, sols), 0);
  Isometry3d nan = Isometry3d::Identity();
  nan.translation() = Vector3d(std::nan(""), 0, 0);
  EXPECT_EQ(k.ik_tool(nan, sols), 0);
}

TEST(Ur5Kinematics, NearestSolutionIsTheGeneratorWhenStartingNearIt) {
  Ur5Kinematics k;
  std::mt19937_64 rng(13);
  std::normal_distribution<double> noise(0, 0.01);
  for (int i = 0; i < 1000; ++i) {
    Joints q = random_joints(rng, -2 * std::numbers::pi, 2 * std::numbers::pi);
    ASSERT_TRUE(k.limits().wrap(q, q));  // the generator inside the UR5's limits (elbow ±π)
    Joints near = q;
    for (double& x : near) x += noise(rng);
    const auto best = k.ik_nearest(k.tool_pose(q), near);
    ASSERT_TRUE(best.has_value());
    // Exactly the generator (not just mod 2π), unless a perturbation crossed a limit.
    if (k.limits().contains(near)) {
      ASSERT_LT(max_joint_delta(*best, q), 1e-6);
    }
    // And it is the nearest of all solutions.
    IkSolutions sols;
    k.ik_tool(k.tool_pose(q), sols, &near);
    for (const Joints& s : sols) ASSERT_LE(weighted_distance(*best, near), weighted_distance(s, near) + 1e-12);
  }
}

TEST(JointLimits, WrapChoosesEquivalentAngleNearestReferenceInsideLimits) {
  JointLimits l;
  double out = 0;
  ASSERT_TRUE(l.wrap_joint(0, -0.5, 5.5, out));
  EXPECT_NEAR(out, -0.5 + kTwoPi, 1e-12);
  ASSERT_TRUE(l.wrap_joint(0, 0.5, -5.0, out));
  EXPECT_NEAR(out, 0.5 - kTwoPi, 1e-12);
  ASSERT_TRUE(l.wrap_joint(0, 20.0, 0.0, out));
  EXPECT_NEAR(out, 20.0 - 3 * kTwoPi, 1e-12);
  l.lower[2] = 0.0;
  l.upper[2] = 1.0;
  EXPECT_FALSE(l.wrap_joint(2, 2.0, 0.0, out));  // 2 + 2πk never in [0, 1]
  ASSERT_TRUE(l.wrap_joint(2, 0.5 - kTwoPi, -9.0, out));
  EXPECT_NEAR(out, 0.5, 1e-12);
  EXPECT_FALSE(l.wrap_joint(0, std::nan(""), 0.0, out));
}

}  // namespace
}  // namespace rtamp::robot
