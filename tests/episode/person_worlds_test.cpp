// One person for every world: the same Person (world/person.hpp) driving the
// symbolic world and the MuJoCo world through exec::PersonWorld, with the arm
// at rest, makes the same interventions at the same times (MuJoCo applies
// them at the physics step that reaches the time) with the same outcome, and
// both worlds then hold every thing in the same place.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rtamp/episode/sim_world.hpp"
#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {
namespace {

using Kind = world::Intervention::Kind;

struct Seen {
  double time;
  std::string what;
  bool applied;
};

std::vector<Seen> drive(exec::World& w, world::Person& person, double until, world::Placement* end) {
  exec::PersonWorld acted(w, person);
  std::vector<Seen> out;
  while (acted.time() < until) {
    acted.advance(0.02);
    for (const auto& e : acted.take_events()) out.push_back({e.time, e.what.to_string(), e.applied});
  }
  *end = acted.intervenable()->true_placement();
  return out;
}

TEST(PersonWorlds, TheSamePersonActsAlikeOnTheSymbolicAndTheMujocoWorld) {
  const world::Scenario s = world::load_scenario("3-block");
  for (std::uint64_t seed : {3u, 8u}) {
    world::PersonOptions po;
    po.rate = 0.4;
    po.end = 12;
    po.kinds = {Kind::Relocate, Kind::Remove};
    po.script = s.interventions;
    po.seed = seed;
    world::Person p1(s, po), p2(s, po);
    exec::SymbolicWorld sym(s);
    SimWorld mj(s, sim::SessionOptions{});
    world::Placement end_sym, end_mj;
    const auto a = drive(sym, p1, 12, &end_sym);
    const auto b = drive(mj, p2, 12, &end_mj);
    SCOPED_TRACE("seed " + std::to_string(seed));
    ASSERT_GE(a.size(), 2u);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].what, b[i].what);
      EXPECT_NEAR(a[i].time, b[i].time, 0.002 + 1e-9);
      EXPECT_EQ(a[i].applied, b[i].applied) << a[i].what;
    }
    EXPECT_EQ(end_sym, end_mj);
  }
}

}  // namespace
}  // namespace rtamp::episode
