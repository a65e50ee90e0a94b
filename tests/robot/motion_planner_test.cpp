// Joint-space planning around obstacles with synthetic collision checkers: a
// forbidden box in joint space and a sphere in the workspace checked with FK.
// Oracle: every returned segment re-checked at a finer resolution than the planner's.
#include "rtamp/robot/motion_planner.hpp"

#include <gtest/gtest.h>

#include "rtamp/robot/ur5_kinematics.hpp"

namespace rtamp::robot {
namespace {

void expect_free_path(const JointPathResult& r, const Joints& from, const Joints& to, CollisionChecker& c) {
  ASSERT_TRUE(r.ok) << r.why;
  ASSERT_GE(r.path.size(), 2u);
  EXPECT_EQ(r.path.front(), from);
  EXPECT_EQ(r.path.back(), to);
  for (std::size_t i = 0; i + 1 < r.path.size(); ++i) EXPECT_FALSE(segment_collides(c, r.path[i], r.path[i + 1], 0.002));
}

TEST(MotionPlanner, DirectSegmentWhenFreeOrNoChecker) {
  const Joints a{0, 0, 0, 0, 0, 0}, b{1, -1, 0.5, 0, 0.2, 0};
  auto r = plan_joint_path(a, b, nullptr);
  ASSERT_TRUE(r.ok);
  EXPECT_FALSE(r.planned);
  EXPECT_EQ(r.path, (std::vector<Joints>{a, b}));
  FunctionCollisionChecker never([](const Joints&) { return false; });
  r = plan_joint_path(a, b, &never);
  ASSERT_TRUE(r.ok);
  EXPECT_FALSE(r.planned);
  EXPECT_EQ(r.path.size(), 2u);
}

TEST(MotionPlanner, GoesAroundAForbiddenJointBoxDeterministically) {
  // Box |q0| < 0.3, |q1| < 1 blocks the straight segment from q0 = −1 to q0 = 1.
  FunctionCollisionChecker box([](const Joints& q) { return std::abs(q[0]) < 0.3 && std::abs(q[1]) < 1.0; });
  const Joints a{-1, 0, 0, 0, 0, 0}, b{1, 0, 0, 0, 0, 0};
  PlannerOptions o;
  o.seed = 7;
  const auto r = plan_joint_path(a, b, &box, o);
  EXPECT_TRUE(r.planned);
  // Segments are checked every `resolution` rad, so a segment may clip a corner by less
  // than that: the oracle re-checks finely against the box shrunk by the resolution.
  FunctionCollisionChecker inner([](const Joints& q) { return std::abs(q[0]) < 0.28 && std::abs(q[1]) < 0.98; });
  ASSERT_NO_FATAL_FAILURE(expect_free_path(r, a, b, inner));
  // The detour must pass |q1| >= 1 somewhere: path length at least the box corner route.
  bool outside = false;
  for (const Joints& q : r.path) outside |= std::abs(q[1]) >= 1.0;
  EXPECT_TRUE(outside);
  const auto again = plan_joint_path(a, b, &box, o);
  EXPECT_EQ(again.path, r.path);  // same seed, same path
}

TEST(MotionPlanner, AvoidsAWorkspaceSphereCheckedWithForwardKinematics) {
  Ur5Kinematics arm;
  const Joints a{-0.8, -1.3, 1.5, -1.77, -1.57, 0}, b{0.8, -1.3, 1.5, -1.77, -1.57, 0};
  Joints mid = a;
  mid[0] = 0;
  const Eigen::Vector3d centre = arm.tool_point(mid);
  const double radius = 0.12;
  // Tool point and the wrist frames must stay out of the sphere.
  FunctionCollisionChecker sphere([&](const Joints& q) {
    const auto f = arm.link_frames(q);
    if ((arm.tool_point(q) - centre).norm() < radius) return true;
    for (int i = 4; i <= 6; ++i)
      if ((f[static_cast<std::size_t>(i)].translation() - centre).norm() < radius) return true;
    return false;
  });
  ASSERT_FALSE(sphere.config_collides(a));
  ASSERT_FALSE(sphere.config_collides(b));
  ASSERT_TRUE(sphere.config_collides(mid));
  const auto r = plan_joint_path(a, b, &sphere, PlannerOptions{});
  EXPECT_TRUE(r.planned);
  ASSERT_NO_FATAL_FAILURE(expect_free_path(r, a, b, sphere));
}

TEST(MotionPlanner, ReportsCollidingEndsAndUnreachableGoals) {
  FunctionCollisionChecker at_origin([](const Joints& q) { return max_joint_delta(q, Joints{}) < 0.1; });
  auto r = plan_joint_path(Joints{}, Joints{1, 0, 0, 0, 0, 0}, &at_origin);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.why, "start configuration collides");
  r = plan_joint_path(Joints{1, 0, 0, 0, 0, 0}, Joints{}, &at_origin);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.why, "goal configuration collides");
  // Goal enclosed by a shell in joint space: no path exists.
  const Joints goal{1, 1, 1, 1, 1, 1};
  FunctionCollisionChecker shell([&](const Joints& q) {
    const double d = max_joint_delta(q, goal);
    return d > 0.2 && d < 0.5;
  });
  PlannerOptions o;
  o.max_iterations = 300;
  r = plan_joint_path(Joints{}, goal, &shell, o);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.planned);
  EXPECT_NE(r.why.find("no collision-free joint path"), std::string::npos);
}

}  // namespace
}  // namespace rtamp::robot
