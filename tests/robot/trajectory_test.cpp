// Trajectories: limits respected (checked by finite differences of the sampled
// q(t), an oracle independent of the profile formulas), synchronisation, straight
// Cartesian lines, and tool path length against closed-form geometry.
#include "rtamp/robot/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace rtamp::robot {
namespace {

TEST(TrapezoidProfile, ReachesDistanceWithinLimits) {
  for (double D : {0.01, 0.5, 1.0, 3.0, 10.0}) {
    const auto p = TrapezoidProfile::make(D, 1.2, 2.5);
    double s = 0, sd = 0;
    p.eval(p.duration(), s, sd);
    EXPECT_NEAR(s, D, 1e-12);
    EXPECT_EQ(sd, 0.0);
    const double dt = 1e-4;
    double prev_s = 0, prev_sd = 0;
    for (double t = dt; t <= p.duration(); t += dt) {
      p.eval(t, s, sd);
      EXPECT_LE(sd, 1.2 + 1e-12);
      EXPECT_NEAR((s - prev_s) / dt, 0.5 * (sd + prev_sd), 1e-3);  // sd is ds/dt
      EXPECT_LE(std::abs(sd - prev_sd) / dt, 2.5 + 1e-6);
      prev_s = s;
      prev_sd = sd;
    }
  }
  // Minimal time: triangular when short, trapezoid when long.
  EXPECT_NEAR(TrapezoidProfile::make(0.4, 1.0, 2.5).duration(), 2 * std::sqrt(0.4 / 2.5), 1e-12);
  EXPECT_NEAR(TrapezoidProfile::make(3.0, 1.0, 2.0).duration(), 3.0 / 1.0 + 1.0 / 2.0, 1e-12);
}

void check_limits(const Trajectory& tr, const MotionLimits& lim, double acc_slack) {
  const double dt = 5e-4;
  Trajectory::Sample prev = tr.sample(0);
  for (double t = dt; t <= tr.duration() + dt; t += dt) {
    const auto s = tr.sample(t);
    for (std::size_t j = 0; j < kDof; ++j) {
      ASSERT_LE(std::abs(s.qd[j]), lim.vmax[j] * (1 + 1e-9));
      ASSERT_LE(std::abs(s.q[j] - prev.q[j]) / dt, lim.vmax[j] * (1 + 1e-9) + 1e-9);  // q continuous, speed bounded
      ASSERT_LE(std::abs(s.qd[j] - prev.qd[j]) / dt, lim.amax[j] * acc_slack + 1e-6);
    }
    prev = s;
  }
}

TEST(Trajectory, JointPathStopsAtWaypointsSynchronisedWithinLimits) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-2, 2);
  MotionLimits lim;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Joints> path(4);
    for (auto& q : path)
      for (double& x : q) x = u(rng);
    Trajectory tr;
    tr.append_joint_path(path, lim);
    ASSERT_EQ(tr.pieces().size(), 3u);
    EXPECT_EQ(tr.sample(0).q, path[0]);
    EXPECT_EQ(tr.sample(tr.duration()).q, path[3]);
    for (std::size_t i = 0; i < 3; ++i) {
      const auto& p = tr.pieces()[i];
      const auto at = tr.sample(p.t0);
      EXPECT_LT(max_joint_delta(at.q, path[i]), 1e-12);
      // Midway the configuration lies on the straight joint segment (synchronised joints).
      const auto mid = tr.sample(p.t0 + 0.37 * p.duration());
      double f = -1;
      for (std::size_t j = 0; j < kDof; ++j) {
        const double d = path[i + 1][j] - path[i][j];
        if (std::abs(d) < 1e-3) continue;
        const double fj = (mid.q[j] - path[i][j]) / d;
        if (f < 0) f = fj;
        EXPECT_NEAR(fj, f, 1e-9);
      }
      // The limiting joint is at its velocity or acceleration limit (time-optimal profile).
      double vratio = 0;
      for (std::size_t j = 0; j < kDof; ++j)
        vratio = std::max(vratio, std::abs(path[i + 1][j] - path[i][j]) * p.profile.vpeak / (p.count - 1) / lim.vmax[j]);
      EXPECT_LE(vratio, 1 + 1e-9);
    }
    ASSERT_NO_FATAL_FAILURE(check_limits(tr, lim, 1 + 1e-6));
  }
}

TEST(Trajectory, PolylineDwellAndAppend) {
  MotionLimits lim;
  std::vector<Joints> line;
  for (int i = 0; i <= 50; ++i) line.push_back(Joints{0.01 * i, -0.005 * i, 0.02 * i, 0, 0, 0.001 * i * i});
  Trajectory a(line.front());
  a.append_polyline(line, lim);
  ASSERT_EQ(a.pieces().size(), 1u);
  const double t1 = a.duration();
  a.append_dwell(0.5);
  EXPECT_NEAR(a.duration(), t1 + 0.5, 1e-12);
  EXPECT_EQ(a.sample(t1 + 0.25).q, line.back());
  Trajectory b(line.back());
  b.append_joint_path({line.back(), Joints{}}, lim);
  const double ta = a.duration();
  a.append(b);
  EXPECT_NEAR(a.duration(), ta + b.duration(), 1e-12);
  EXPECT_EQ(a.sample(a.duration()).q, Joints{});
  EXPECT_LT(max_joint_delta(a.sample(ta + 0.3).q, b.sample(0.3).q), 1e-12);
  // A curved polyline: velocity bounded; the turns at samples change the velocity
  // direction abruptly (documented), so the acceleration is not checked here.
  ASSERT_NO_FATAL_FAILURE(check_limits(a, lim, 1e9));
  // A straight polyline (what a Cartesian line is, nearly): accelerations bounded too.
  std::vector<Joints> straight;
  for (int i = 0; i <= 40; ++i) straight.push_back(Joints{0.01 * i, -0.005 * i, 0.02 * i, 0, 0.003 * i, 0});
  Trajectory c(straight.front());
  c.append_polyline(straight, lim);
  ASSERT_NO_FATAL_FAILURE(check_limits(c, lim, 1 + 1e-6));
  EXPECT_NEAR(c.duration(), TrapezoidProfile::make(0.8, 1.0, 2.0).duration(), 1e-9);  // joint 3 limits
  EXPECT_THROW(a.append_polyline({Joints{1, 1, 1, 1, 1, 1}, Joints{}}, lim), std::invalid_argument);
}

TEST(CartesianLine, FollowsAStraightSegmentWithConstantOrientation) {
  Ur5Kinematics arm;
  // A top-down pose in front of the robot (the DH base's −x is "front" at q1 = 0).
  const Joints q0{0.3, -1.6, 1.6, -1.57, -1.57, 0.2};
  const Eigen::Isometry3d start = arm.tool_pose(q0);
  Eigen::Isometry3d goal = start;
  goal.translation() += Eigen::Vector3d(0.05, -0.1, -0.12);
  std::string why;
  const auto path = cartesian_line(arm, q0, goal, CartesianOptions{}, &why);
  ASSERT_TRUE(path.has_value()) << why;
  EXPECT_GE(path->size(), static_cast<std::size_t>(std::ceil(0.1612 / 0.005)));
  const Eigen::Vector3d a = start.translation(), d = (goal.translation() - a).normalized();
  for (const Joints& q : *path) {
    const Eigen::Isometry3d t = arm.tool_pose(q);
    const Eigen::Vector3d r = t.translation() - a;
    EXPECT_LT((r - r.dot(d) * d).norm(), 1e-9);
    EXPECT_LT(rotation_error(t, start), 1e-9);
  }
  EXPECT_LT(position_error(arm.tool_pose(path->back()), goal), 1e-9);
  // Path length of the straight line equals its Euclidean length (to the sampling's accuracy).
  EXPECT_NEAR(tool_path_length(arm, *path), (goal.translation() - a).norm(), 1e-4);
}

TEST(CartesianLine, RejectsUnreachableTargets) {
  Ur5Kinematics arm;
  const Joints q0{0.3, -1.6, 1.6, -1.57, -1.57, 0.2};
  Eigen::Isometry3d goal = arm.tool_pose(q0);
  goal.translation() += Eigen::Vector3d(1.5, 0, 0);
  std::string why;
  EXPECT_FALSE(cartesian_line(arm, q0, goal, CartesianOptions{}, &why).has_value());
  EXPECT_NE(why.find("unreachable"), std::string::npos);
}

TEST(CartesianLine, RejectsAJointJumpThroughTheWristSingularity) {
  // Wrist nearly singular (θ5 = 0.02): a line that carries the tool across the
  // singular set forces θ4/θ6 to swing; with a tight jump limit the line is rejected.
  Ur5Kinematics arm;
  const Joints q0{0.3, -1.2, 1.4, -0.5, 0.02, 0.2};
  const Eigen::Isometry3d start = arm.tool_pose(q0);
  Joints q1 = q0;
  q1[4] = -0.02;
  const Eigen::Isometry3d goal = arm.tool_pose(q1);
  CartesianOptions o;
  o.max_joint_jump = 0.05;
  std::string why;
  const auto path = cartesian_line(arm, q0, goal, o, &why);
  if (path) {
    // If accepted, it must respect the jump limit everywhere.
    for (std::size_t i = 1; i < path->size(); ++i) EXPECT_LE(max_joint_delta((*path)[i], (*path)[i - 1]), 0.05 + 1e-12);
  } else {
    EXPECT_NE(why.find("joint jump"), std::string::npos) << why;
  }
  EXPECT_GT(position_error(start, goal) + rotation_error(start, goal), 0.0);
}

TEST(ToolPathLength, SingleJointRotationIsAnArc) {
  Ur5Kinematics arm;
  const Joints a{0.0, -1.2, 1.4, -1.0, -1.57, 0.0};
  Joints b = a;
  b[0] = 1.3;
  const Eigen::Vector3d p = arm.tool_point(a);
  const double radius = std::hypot(p.x(), p.y());  // distance from joint 1's axis (base z)
  EXPECT_NEAR(tool_path_length(arm, {a, b}, 0.001), radius * 1.3, 1e-6 * radius + 1e-7);
  Trajectory tr(a);
  tr.append_joint_path({a, b, a}, MotionLimits{});
  tr.append_dwell(1.0);
  EXPECT_NEAR(tool_path_length(arm, tr, 0.001), 2 * radius * 1.3, 2e-6);
}

}  // namespace
}  // namespace rtamp::robot
