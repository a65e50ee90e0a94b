// The generated MJCF loads, has the promised structure, and the arm holds its pose.
#include <gtest/gtest.h>

#include <cmath>

#include "rtamp/sim/mjcf_builder.hpp"
#include "rtamp/sim/simulation.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

TEST(Mjcf, LoadsWithPromisedStructure) {
  for (bool tray : {false, true}) {
    Simulation sim(testing::three_block(tray));
    const mjModel* m = sim.model();
    EXPECT_EQ(m->nu, 8);
    for (int j = 0; j < 6; ++j) EXPECT_EQ(m->jnt_type[j], mjJNT_HINGE);
    EXPECT_EQ(m->jnt_type[6], mjJNT_SLIDE);
    EXPECT_EQ(m->jnt_type[7], mjJNT_SLIDE);
    const int nthings = 3 + (tray ? 1 : 0) + 4 + 1;
    EXPECT_EQ(static_cast<int>(sim.things().size()), nthings);
    EXPECT_EQ(m->neq, nthings);
    for (int e = 0; e < m->neq; ++e) EXPECT_EQ(m->eq_active[e], 0);
    EXPECT_GE(mj_name2id(m, mjOBJ_CAMERA, "overview"), 0);
    EXPECT_GE(sim.find("o1"), 0);
    EXPECT_EQ(sim.find("nope"), -1);
  }
}

TEST(Mjcf, ArmHoldsPoseAgainstGravity) {
  Simulation sim(testing::three_block(true));
  const robot::Joints q0 = sim.arm_q();
  robot::Joints q = {0.3, -1.2, 1.4, -1.8, -1.5707963, 0.2};
  sim.set_arm_target(q);
  sim.step(1500);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(sim.arm_q()[j], q[j], 1e-3) << "joint " << j;
  (void)q0;
  // Blocks rest on the table.
  for (const char* n : {"o1", "o2", "o3"}) {
    auto p = sim.pose(sim.find(n));
    EXPECT_NEAR(p.translation().z(), 0.02, 2e-3) << n;
  }
  EXPECT_EQ(sim.warnings().total(), 0);
}

TEST(Mjcf, ArmMotorTorqueStaysWithinTheEffortLimits) {
  // A target 1.2 rad away on the pan and wrist joints (the arm stays clear of the table),
  // with no trajectory: the servo alone would ask for thousands of N m. The motor torque (actuator + applied feed-forward − what MuJoCo's
  // implicit damping takes back, the servo's velocity feedback) must stay within the UR5's
  // effort limits (150 / 28 N m), and the arm still gets there.
  Simulation sim(testing::three_block(false));
  const mjModel* m = sim.model();
  const mjData* d = sim.data();
  robot::Joints q = sim.arm_q();
  const bool moved[6] = {true, false, false, true, true, true};
  for (int j = 0; j < 6; ++j)
    if (moved[j]) q[j] += 1.2;
  sim.set_arm_target(q);
  const double limit[6] = {150, 150, 150, 28, 28, 28};
  double peak[6] = {0, 0, 0, 0, 0, 0}, servo_peak[6] = {0, 0, 0, 0, 0, 0};
  for (int k = 0; k < 3000; ++k) {
    double qvel[6];
    for (int j = 0; j < 6; ++j) qvel[j] = d->qvel[j];
    sim.step();
    // This step's motor torque: the actuator force and the applied feed-forward it used,
    // minus the damping × qvel the feed-forward added back for MuJoCo to take away.
    for (int j = 0; j < 6; ++j) {
      peak[j] = std::max(peak[j], std::abs(d->qfrc_actuator[j] + d->qfrc_applied[j] - m->dof_damping[j] * qvel[j]));
      servo_peak[j] = std::max(servo_peak[j], std::abs(d->qfrc_actuator[j]));
    }
  }
  EXPECT_GT(sim.torque_limited_steps(), 0);
  for (int j = 0; j < 6; ++j) {
    EXPECT_EQ(m->actuator_forcerange[2 * j + 1], limit[j]);
    EXPECT_LE(peak[j], limit[j] * (1 + 1e-9)) << "joint " << j;
    if (moved[j]) {
      EXPECT_EQ(servo_peak[j], limit[j]) << "joint " << j;  // the servo saturated: the test bites
    }
    EXPECT_NEAR(sim.arm_q()[j], q[j], 1e-3) << "joint " << j;
  }
}

}  // namespace
}  // namespace rtamp::sim
