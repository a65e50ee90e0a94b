// The `ik` model behind the planner's interface, on the built-in 3-block-tray
// scenario: the adapter's costs are the model's, for every enabled move of the
// initial state, and respect the interface's lower-bound contract.
#include "rtamp/robot/ik_motion_cost.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rtamp/task/transition_system.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::robot {
namespace {

Eigen::Vector3d v(const world::Vec3& x) { return {x[0], x[1], x[2]}; }

TEST(IkMotionCost, CostsEveryMoveOfTheTrayScenario) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const task::System ts(s);
  IkMotionCost ik(IkMotionCost::params_for(s));
  EXPECT_EQ(ik.name(), "ik");
  EXPECT_TRUE(ik.expensive());
  EXPECT_TRUE(ik.depends() & plan::kDependsThing);
  const task::State s0 = ts.initial();
  int moves = 0;
  ts.for_each_move(s0, [&](const task::Action& a) {
    const plan::MotionQuery q = plan::MotionCostModel::query(ts, s0, a);
    const double c = ik.cost(ts, s0, a);
    EXPECT_TRUE(std::isfinite(c)) << ts.action_name(a);
    EXPECT_EQ(c, ik.model().move_cost(v(q.hand), v(q.from), v(q.to), q.container));
    EXPECT_LE(ik.lower_bound(q, false), c);
    EXPECT_LE(ik.lower_bound(q, true), ik.lower_bound(q, false));
    ++moves;
  });
  EXPECT_GT(moves, 0);
  // Blocks at the same location share one cold computation per destination.
  EXPECT_LT(ik.model().cold_computations(), static_cast<std::uint64_t>(moves));
  EXPECT_EQ(ik.cost(ts, s0, task::Action::stay()), 0.0);
}

}  // namespace
}  // namespace rtamp::robot
