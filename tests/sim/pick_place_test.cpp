// End to end in simulation: blocks picked and placed into regions and trays end up
// there as perception reports it; a tray carried to another region keeps its blocks.
#include <gtest/gtest.h>

#include "rtamp/sim/perception.hpp"
#include "rtamp/sim/skill_runner.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

struct Rig {
  explicit Rig(const world::Scenario& s) : sim(s), ctl(sim), runner(sim, ctl), perception(sim) {}
  std::string where(const std::string& n) {
    auto p = perception.observe();
    const Observation* o = p.find(n);
    return o ? o->location : "absent";
  }
  Simulation sim;
  Controller ctl;
  SkillRunner runner;
  Perception perception;
};

TEST(SimPickPlace, OneBlockToR2) {
  Rig rig(testing::three_block(false));
  rig.sim.step(100);
  EXPECT_EQ(rig.where("o1"), "r1");
  ActionResult r = rig.runner.move("o1", "r2");
  EXPECT_EQ(r.status, Status::Success) << r.reason;
  EXPECT_GT(r.cost, 0.3);
  rig.sim.step(200);
  EXPECT_EQ(rig.where("o1"), "r2");
  EXPECT_EQ(rig.where("o2"), "r1");
  EXPECT_EQ(rig.sim.held(), -1);
  EXPECT_EQ(rig.sim.warnings().total(), 0);
  EXPECT_EQ(rig.sim.torque_limited_steps(), 0);  // inside the UR5's effort limits
}

}  // namespace
}  // namespace rtamp::sim
