// The `ik` cost model: cached values equal cold ones, costs agree with the skill
// plan the arm would run, the lower bound holds (oracle: the costs themselves over a
// grid of table points), unreachable moves cost infinity, the cache counts.
#include "rtamp/robot/ik_cost_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace rtamp::robot {
namespace {

// The 3-block-tray scene: base at the origin, yaw 0; r1 (0.40, 0.32), r2 (0.40, −0.32).
IkCostParams scene() {
  IkCostParams p;
  p.home_point = Eigen::Vector3d(0, 0, 0.5);
  return p;
}

TEST(IkCostModel, HomeConfigurationHoldsTheToolAboveTheTable) {
  IkCostModel m(scene());
  const Joints home = m.hand_configuration(Eigen::Vector3d(0, 0, 0.5));
  EXPECT_EQ(home, m.params().home);
  EXPECT_GT(m.arm().tool_point(home).z(), 0.1);
  // A hand at a region hovers above its point, tool down.
  const Eigen::Vector3d r1(0.40, 0.32, 0);
  const Eigen::Isometry3d t = m.arm().tool_pose(m.hand_configuration(r1));
  EXPECT_LT((t.translation() - (r1 + Eigen::Vector3d(0, 0, m.hover_height()))).norm(), 1e-6);
  EXPECT_NEAR(t.linear()(2, 2), -1.0, 1e-9);
}

TEST(IkCostModel, CachedEqualsColdAndAgreesWithTheSkillPlan) {
  IkCostModel m(scene());
  const Eigen::Vector3d home(0, 0, 0.5), r1(0.40, 0.32, 0), r2(0.40, -0.32, 0);
  const double c1 = m.move_cost(home, r1, r2, false);
  ASSERT_TRUE(std::isfinite(c1));
  EXPECT_EQ(m.cold_computations(), 1u);
  EXPECT_GT(m.cold_seconds(), 0.0);
  const double c2 = m.move_cost(home, r1, r2, false);
  EXPECT_EQ(c1, c2);
  EXPECT_EQ(m.cold_computations(), 1u);
  EXPECT_EQ(m.cache_hits(), 1u);
  // Within the quantum: same entry.
  EXPECT_EQ(m.move_cost(home, r1 + Eigen::Vector3d(3e-5, 0, 0), r2, false), c1);
  EXPECT_EQ(m.cold_computations(), 1u);
  // The cost is the tool path length of the plan the arm would execute.
  const SkillPlan plan = m.move_plan(home, r1, r2, false);
  ASSERT_TRUE(plan.ok) << plan.why;
  EXPECT_NEAR(c1, plan.cost, 1e-12);
  EXPECT_NEAR(c1, tool_path_length(m.arm(), plan.trajectory, 0.002), 1e-3);  // finer sampling, same path
  // A container is grasped elsewhere: a different entry, a different cost.
  const double ct = m.move_cost(home, r1, r2, true);
  EXPECT_EQ(m.cold_computations(), 2u);
  EXPECT_NE(ct, c1);
  // A fresh model computes the same value cold.
  IkCostModel fresh(scene());
  EXPECT_EQ(fresh.move_cost(home, r1, r2, false), c1);
  m.clear();
  EXPECT_EQ(m.cache_size(), 0u);
}

TEST(IkCostModel, LowerBoundNeverExceedsTheCost) {
  IkCostModel m(scene());
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(0.2, 0.6), y(-0.45, 0.45);
  int finite = 0;
  for (int i = 0; i < 60; ++i) {
    // Braced lists: their draws are in order whatever the compiler.
    const Eigen::Vector3d h = i % 5 == 0 ? Eigen::Vector3d(0, 0, 0.5) : Eigen::Vector3d{x(rng), y(rng), 0};
    const Eigen::Vector3d p{x(rng), y(rng), 0}, t{x(rng), y(rng), 0};
    for (bool container : {false, true}) {
      const double c = m.move_cost(h, p, t, container);
      if (!std::isfinite(c)) continue;
      ++finite;
      EXPECT_LE(m.lower_bound(h, p, t, false), c + 1e-9) << i << " container " << container;
      EXPECT_LE(m.lower_bound(h, p, t, true), m.lower_bound(h, p, t, false));
      EXPECT_GE(m.lower_bound(h, p, t, true), 0.0);
      EXPECT_LE(m.carry_bound(p, t), c + 1e-9) << i << " container " << container;
    }
  }
  EXPECT_GT(finite, 100);
}

TEST(IkCostModel, ABoundSolvesTheHandsIkOncePerHandPoint) {
  IkCostModel m(scene());
  const Eigen::Vector3d h(0.4, 0.3, 0), p(0.4, -0.3, 0), t(0.3, 0.1, 0);
  const double first = m.lower_bound(h, p, t, false);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(m.lower_bound(h, p, t, i % 2 == 0), i % 2 == 0 ? m.lower_bound(h, p, t, true) : first);
  EXPECT_EQ(m.bound_points(), 1u);
  (void)m.lower_bound(p, h, t, false);
  EXPECT_EQ(m.bound_points(), 2u);
  // The kept tool point is the one a fresh model computes.
  IkCostModel fresh(scene());
  EXPECT_EQ(fresh.lower_bound(h, p, t, false), first);
}

TEST(IkCostModel, UnreachableMovesCostInfinity) {
  IkCostModel m(scene());
  EXPECT_EQ(m.move_cost(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(2.0, 0, 0), Eigen::Vector3d(0.4, 0.3, 0), false),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.cold_computations(), 1u);
}

TEST(IkCostModel, CollisionCheckerChangesCostsAndClearsTheCache) {
  IkCostModel m(scene());
  const Eigen::Vector3d home(0, 0, 0.5), r1(0.40, 0.32, 0), r2(0.40, -0.32, 0);
  const double free_cost = m.move_cost(home, r1, r2, false);
  FunctionCollisionChecker everywhere([](const Joints&) { return true; });
  m.set_collision_checker(&everywhere);
  EXPECT_EQ(m.cache_size(), 0u);
  EXPECT_EQ(m.move_cost(home, r1, r2, false), std::numeric_limits<double>::infinity());
  FunctionCollisionChecker never([](const Joints&) { return false; });
  m.set_collision_checker(&never);
  EXPECT_EQ(m.move_cost(home, r1, r2, false), free_cost);
}

}  // namespace
}  // namespace rtamp::robot
