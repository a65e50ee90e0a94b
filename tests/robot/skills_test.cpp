// Pick and place skill plans: geometry of the phases (checked with FK, independent
// of how the plan was built), gripper events, cost = tool path length, yaw choice,
// planning around a synthetic obstacle, and failures.
#include "rtamp/robot/skills.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtamp::robot {
namespace {

constexpr double kPi = std::numbers::pi;

struct Fixture {
  Ur5Kinematics arm;
  Joints home{};
  Fixture() {
    Ur5Kinematics::Config c;
    c.base = Ur5Kinematics::base_pose(world::Robot{"ur5", {0, 0, 0}, kPi});  // arm's front along +x
    arm = Ur5Kinematics(c);
    home = *arm.ik_nearest(top_down_pose({0.35, 0.0, 0.35}, 0.0), Joints{0, -kPi / 2, kPi / 2, -kPi / 2, -kPi / 2, 0});
  }
};

bool is_top_down(const Eigen::Isometry3d& t) { return (t.linear().col(2) - Eigen::Vector3d(0, 0, -1)).norm() < 1e-6; }

TEST(Skills, PickPhasesEventsAndCost) {
  Fixture f;
  const ThingPose block{{0.5, 0.15, 0.0}, 0.3};
  const Grasp g = Grasp::block({0.04, 0.04, 0.04});
  const SkillPlan p = plan_pick(f.arm, f.home, block, g);
  ASSERT_TRUE(p.ok) << p.why;
  const Eigen::Vector3d grasp_point(0.5, 0.15, 0.02), pre = grasp_point + Eigen::Vector3d(0, 0, 0.1);
  EXPECT_EQ(p.trajectory.start(), f.home);
  EXPECT_LT((f.arm.tool_point(p.trajectory.sample(p.t_transit).q) - pre).norm(), 1e-6);
  const Eigen::Isometry3d at_grasp = f.arm.tool_pose(p.trajectory.sample(p.t_approach).q);
  EXPECT_LT((at_grasp.translation() - grasp_point).norm(), 1e-6);
  EXPECT_TRUE(is_top_down(at_grasp));
  // Tool yaw aligned with the block modulo its 4-fold symmetry.
  const double yaw = std::atan2(at_grasp.linear()(1, 0), at_grasp.linear()(0, 0));
  EXPECT_NEAR(std::remainder(yaw - 0.3, kPi / 2), 0.0, 1e-6);
  ASSERT_EQ(p.events.size(), 1u);
  EXPECT_EQ(p.events[0].kind, GripperEvent::Kind::Close);
  EXPECT_NEAR(p.events[0].time, p.t_approach, 1e-12);
  // The fingers do not move while closing.
  EXPECT_EQ(p.trajectory.sample(p.t_approach + 0.1).q, p.trajectory.sample(p.t_gripper).q);
  EXPECT_LT((f.arm.tool_point(p.end) - pre).norm(), 1e-6);
  // Approach and retreat are vertical: the tool stays on the line above the grasp point.
  for (double t = p.t_transit; t <= p.trajectory.duration(); t += 0.01) {
    const Eigen::Vector3d x = f.arm.tool_point(p.trajectory.sample(t).q);
    EXPECT_LT(std::hypot(x.x() - grasp_point.x(), x.y() - grasp_point.y()), 1e-4) << t;
  }
  EXPECT_NEAR(p.cost, tool_path_length(f.arm, p.trajectory, 0.01), 1e-12);
  // Cost bounds: at least straight to the pre-grasp point, down and up again.
  const double straight = (f.arm.tool_point(f.home) - pre).norm();
  EXPECT_GE(p.cost, straight + 0.2 - 1e-6);
  EXPECT_LE(p.cost, 3 * straight + 0.2 + 1e-3);
}

TEST(Skills, PlaceOpensAtTheTargetAndPickAndPlaceAddsUp) {
  Fixture f;
  const Grasp g = Grasp::block({0.04, 0.04, 0.04});
  const ThingPose from{{0.5, 0.15, 0.0}, 0.0}, to{{0.3, -0.35, 0.0}, 0.0};
  const SkillPlan both = plan_pick_and_place(f.arm, f.home, from, to, g);
  ASSERT_TRUE(both.ok) << both.why;
  ASSERT_EQ(both.events.size(), 2u);
  EXPECT_EQ(both.events[0].kind, GripperEvent::Kind::Close);
  EXPECT_EQ(both.events[1].kind, GripperEvent::Kind::Open);
  const Eigen::Isometry3d at_open = f.arm.tool_pose(both.trajectory.sample(both.events[1].time).q);
  EXPECT_LT((at_open.translation() - Eigen::Vector3d(0.3, -0.35, 0.02)).norm(), 1e-6);
  EXPECT_TRUE(is_top_down(at_open));
  const SkillPlan pick = plan_pick(f.arm, f.home, from, g);
  Grasp held = g;
  held.yaw = pick.grasp_yaw;
  const SkillPlan place = plan_place(f.arm, pick.end, to, held);
  ASSERT_TRUE(place.ok);
  EXPECT_NEAR(both.cost, pick.cost + place.cost, 1e-9);
  EXPECT_NEAR(both.cost, tool_path_length(f.arm, both.trajectory, 0.01), 1e-9);
  EXPECT_NEAR(both.trajectory.duration(), pick.trajectory.duration() + place.trajectory.duration(), 1e-9);
  EXPECT_EQ(both.end, place.end);
}

TEST(Skills, TrayGraspStraddlesTheRim) {
  Fixture f;
  const world::Vec3 size{0.24, 0.16, 0.03};
  const Grasp g = Grasp::tray(size, 0.008, 0.01);
  const ThingPose tray{{0.45, -0.2, 0.0}, 0.3};
  const SkillPlan p = plan_pick(f.arm, f.home, tray, g);
  ASSERT_TRUE(p.ok) << p.why;
  const Eigen::Isometry3d t = f.arm.tool_pose(p.trajectory.sample(p.t_approach).q);
  const Eigen::Vector3d tray_x(std::cos(0.3), std::sin(0.3), 0);
  const Eigen::Vector3d expect = tray.position + (0.12 - 0.004) * tray_x + Eigen::Vector3d(0, 0, 0.02);
  EXPECT_LT((t.translation() - expect).norm(), 1e-6);
  EXPECT_NEAR(std::abs(t.linear().col(1).dot(tray_x)), 1.0, 1e-9);  // fingers close across the rim
}

TEST(Skills, PlansAroundAnObstacleWhenTheDirectTransitCollides) {
  Fixture f;
  const Grasp g = Grasp::block({0.04, 0.04, 0.04});
  const ThingPose block{{0.2, 0.45, 0.0}, 0.0};
  const SkillPlan direct = plan_pick(f.arm, f.home, block, g);
  ASSERT_TRUE(direct.ok);
  // A sphere on the direct transit's tool path, at its midpoint.
  const Eigen::Vector3d centre = f.arm.tool_point(direct.trajectory.sample(direct.t_transit / 2).q);
  const double radius = 0.08;
  FunctionCollisionChecker sphere([&](const Joints& q) {
    if ((f.arm.tool_point(q) - centre).norm() < radius) return true;
    const auto fr = f.arm.link_frames(q);
    for (int i = 3; i <= 6; ++i)
      if ((fr[static_cast<std::size_t>(i)].translation() - centre).norm() < radius) return true;
    return false;
  });
  const SkillPlan around = plan_pick(f.arm, f.home, block, g, SkillOptions{}, &sphere);
  ASSERT_TRUE(around.ok) << around.why;
  EXPECT_TRUE(around.planned_around);
  // Deterministic: the same query plans the same detour.
  const SkillPlan again = plan_pick(f.arm, f.home, block, g, SkillOptions{}, &sphere);
  EXPECT_EQ(again.trajectory.waypoints(), around.trajectory.waypoints());
  EXPECT_EQ(again.cost, around.cost);
  const auto& w = around.trajectory.waypoints();
  // Oracle: re-check the whole transit at a fine resolution.
  for (const auto& piece : around.trajectory.pieces()) {
    if (piece.t0 >= around.t_transit - 1e-12) break;
    EXPECT_FALSE(segment_collides(sphere, w[piece.first], w[piece.first + piece.count - 1], 0.005));
  }
}

TEST(Skills, UnreachableThingsFailWithAReason) {
  Fixture f;
  const SkillPlan p = plan_pick(f.arm, f.home, ThingPose{{2.0, 0.0, 0.0}, 0.0}, Grasp::block({0.04, 0.04, 0.04}));
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.why.find("unreachable"), std::string::npos);
  FunctionCollisionChecker everywhere([](const Joints&) { return true; });
  const SkillPlan q =
      plan_pick(f.arm, f.home, ThingPose{{0.5, 0.0, 0.0}, 0.0}, Grasp::block({0.04, 0.04, 0.04}), {}, &everywhere);
  EXPECT_FALSE(q.ok);
  EXPECT_NE(q.why.find("collides"), std::string::npos);
}

}  // namespace
}  // namespace rtamp::robot

namespace rtamp::robot {
namespace {

// An arm stopped in contact (its start configuration collides): the plan first
// backs the tool straight up by the approach height, then transits from there.
TEST(Skills, StartInContactBacksStraightUpFirst) {
  Fixture f;
  const Joints low = *f.arm.ik_nearest(top_down_pose({0.35, 0.0, 0.03}, 0.0), f.home);
  const double low_z = f.arm.tool_point(low).z();
  // Everything with the tool below 6 cm collides (the start does; pre-grasp poses do not).
  FunctionCollisionChecker checker([&](const Joints& q) { return f.arm.tool_point(q).z() < 0.06; });
  const ThingPose block{{0.5, 0.15, 0.0}, 0.0};
  const SkillPlan p = plan_pick(f.arm, low, block, Grasp::block({0.04, 0.04, 0.04}), SkillOptions{}, &checker);
  ASSERT_TRUE(p.ok) << p.why;
  EXPECT_EQ(p.trajectory.start(), low);
  // The first part of the motion is vertical, up to approach_height above the start.
  const Eigen::Vector3d start = f.arm.tool_point(low);
  double t = 0;
  for (; t < p.t_transit; t += 0.01) {
    const Eigen::Vector3d x = f.arm.tool_point(p.trajectory.sample(t).q);
    if (x.z() >= low_z + SkillOptions{}.approach_height - 1e-6) break;
    EXPECT_LT(std::hypot(x.x() - start.x(), x.y() - start.y()), 1e-3) << t;
  }
  EXPECT_LT(t, p.t_transit) << "the tool never rose by the approach height before the pre-grasp pose";
  // Without a checker there is no escape: the transit starts at once.
  const SkillPlan q = plan_pick(f.arm, low, block, Grasp::block({0.04, 0.04, 0.04}));
  ASSERT_TRUE(q.ok);
  EXPECT_LT(q.t_transit, p.t_transit);
}

}  // namespace
}  // namespace rtamp::robot
