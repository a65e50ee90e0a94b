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

}  // namespace
}  // namespace rtamp::sim
