// Perception: locations by the planner's geometry, noise and misses seeded.
#include <gtest/gtest.h>

#include "rtamp/sim/perception.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::sim {
namespace {

TEST(SimPerception, AgreesWithInitialPlacement) {
  const auto sc = world::load_scenario("3-block-tray");
  Simulation sim(sc);
  sim.step(100);
  Perception p(sim);
  EXPECT_EQ(p.observe().placement(), world::initial_placement(sc));
}

TEST(SimPerception, NoiseAndMissesAreSeeded) {
  const auto sc = world::load_scenario("3-block");
  Simulation sim(sc);
  PerceptionOptions o;
  o.position_sigma = 0.01;
  o.miss_probability = 0.3;
  o.seed = 7;
  Perception a(sim, o), b(sim, o);
  o.seed = 8;
  Perception c(sim, o);
  bool differs = false;
  for (int k = 0; k < 20; ++k) {
    Percept pa = a.observe(), pb = b.observe(), pc = c.observe();
    ASSERT_EQ(pa.things.size(), pb.things.size());
    for (std::size_t i = 0; i < pa.things.size(); ++i) {
      EXPECT_EQ(pa.things[i].position, pb.things[i].position);
      EXPECT_EQ(pa.things[i].detected, pb.things[i].detected);
      differs |= pa.things[i].position != pc.things[i].position;
    }
  }
  EXPECT_TRUE(differs);
  o.miss_probability = 1;
  Perception blind(sim, o);
  EXPECT_TRUE(blind.observe().placement().things.empty());
}

TEST(SimPerception, HeldThingIsInHand) {
  Simulation sim(world::load_scenario("3-block"));
  sim.attach(sim.find("o1"));
  Perception p(sim);
  EXPECT_EQ(*p.observe().placement().location_of("o1"), kInHand);
  sim.detach();
  EXPECT_EQ(*p.observe().placement().location_of("o1"), "r1");
}

}  // namespace
}  // namespace rtamp::sim
