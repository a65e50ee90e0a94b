// The packing measurement (the table in docs/scenario.md "Footprints"): for
// each region side and block side of a grid, the MuJoCo arm moves blocks one by one
// from a store into an empty region with the rule book switched off
// (SkillRunnerOptions::space_rules = false: what the arm itself can place) until a
// move fails or a placed block is no longer perceived in the region. Given one block
// more than the rule book admits (world::refusal, with the capacity out of the way),
// it must place exactly as many as the rule admits: not fewer (what the planner
// promises fits is what the arm can place), not more (the rule refuses nothing the
// arm can do). Prints the measured table.
#include <gtest/gtest.h>

#include <cstdio>

#include "rtamp/sim/session.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::sim {
namespace {

// How many blocks of side `b` the rule book admits in an empty region of side `a`.
int admitted(double a, double b) {
  const world::Body block{{b, b, b}, false};
  world::LocationNow at;
  at.kind = world::LocationNow::Kind::Region;
  at.usable = {a, a};
  at.capacity = 1000;
  int n = 0;
  while (world::refusal("o", block, "dst", at).empty() && n < 100) {
    ++n;
    ++at.count;
    at.used += world::cell_units(block, at.usable, false);
  }
  return n;
}

// A store of n blocks of side b (5 cm apart, on a grid from the store's corner
// nearest the robot) and an empty region "dst" of side a, in front of a UR5.
world::Scenario scene(double a, double b, int n) {
  world::Scenario s;
  s.name = "packing";
  s.regions.push_back({"store", {0.40, -0.28, 0}, {0.42, 0.42, 0}, 1000, {}});
  s.regions.push_back({"dst", {0.42, 0.26, 0}, {a, a, 0}, 1000, {}});
  const double pitch = b + 0.05;
  for (int k = 0; k < n; ++k) {
    const double x = 0.40 - 0.21 + 0.02 + b / 2 + (k % 4) * pitch;
    const double y = -0.28 + 0.21 - 0.02 - b / 2 - (k / 4) * pitch;
    s.objects.push_back({"o" + std::to_string(k + 1), "block", {x, y, 0}, {b, b, b}, {}});
  }
  return s;
}

int placed_by_arm(double a, double b, int n) {
  SessionOptions o;
  o.skills.space_rules = false;
  Session s(scene(a, b, n), o);
  s.sim().step(50);
  int placed = 0;
  for (int k = 1; k <= n; ++k) {
    const ActionResult r = s.execute(parse_actions("move o" + std::to_string(k) + " dst").front());
    if (r.status != Status::Success) break;
    s.sim().step(150);
    const Percept p = s.perception().observe();
    bool all_in = true;
    for (int j = 1; j <= k; ++j) {
      const Observation* obs = p.find("o" + std::to_string(j));
      all_in = all_in && obs && obs->location == "dst";
    }
    if (!all_in) break;
    placed = k;
  }
  return placed;
}

TEST(SimPacking, TheArmPlacesWhatTheRuleAdmits) {
  std::printf("region side | block side | rule admits | arm places (of rule + 1)\n");
  for (double b : {0.04, 0.05})
    for (double a : {0.12, 0.16, 0.20, 0.24}) {
      const int rule = admitted(a, b);
      const int arm = placed_by_arm(a, b, rule + 1);
      std::printf("%.2f m | %.2f m | %d | %d\n", a, b, rule, arm);
      std::fflush(stdout);
      EXPECT_EQ(arm, rule) << "region " << a << " m, blocks " << b << " m";
    }
}

}  // namespace
}  // namespace rtamp::sim
