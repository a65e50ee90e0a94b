// The MuJoCo arm is the robot layer's UR5: FK of robot::Ur5Kinematics equals MuJoCo's
// flange and tcp sites for random configurations (an independent oracle: MuJoCo's own
// kinematics of the generated body tree).
#include <gtest/gtest.h>

#include <random>

#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/sim/simulation.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

void expect_same(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const char* what) {
  EXPECT_LT((a.translation() - b.translation()).norm(), 1e-9) << what;
  EXPECT_LT((a.linear() - b.linear()).norm(), 1e-9) << what;
}

TEST(SimKinematics, RobotFkEqualsMujocoSites) {
  for (double yaw : {0.0, 0.7}) {
    auto s = testing::three_block(true);
    s.robot.base = {0.05, -0.1, 0.02};
    s.robot.yaw = yaw;
    Simulation sim(s);
    robot::Ur5Kinematics::Config cfg;
    cfg.base = robot::Ur5Kinematics::base_pose(s.robot);
    cfg.tool_offset = sim.options().mjcf.arm.tool_offset;
    robot::Ur5Kinematics arm(cfg);
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-3.14159, 3.14159);
    for (int k = 0; k < 200; ++k) {
      robot::Joints q;
      for (double& v : q) v = u(rng);
      sim.set_arm_configuration(q);
      expect_same(arm.flange_pose(q), sim.flange_pose(), "flange");
      expect_same(arm.tool_pose(q), sim.tool_pose(), "tool");
    }
  }
}

TEST(SimKinematics, HomeToolPointsDown) {
  Simulation sim(testing::three_block(false));
  auto t = sim.tool_pose();
  EXPECT_LT((t.linear().col(2) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  EXPECT_GT(t.translation().z(), 0.2);
}

}  // namespace
}  // namespace rtamp::sim
