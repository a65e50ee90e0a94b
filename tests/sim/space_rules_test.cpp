// The MuJoCo world keeps the rule book of space (world/space_rules.hpp):
// the person's additions and relocations into a full location are refused with the
// symbolic world's words (the same interventions applied to an exec::SymbolicWorld of
// the same scenario give the same outcome and detail), the arm does not place into a
// full location, and the person sets things down with the arm's clearance
// (world::kPlaceGap), so the arm's next pick does not knock a neighbour out; a place the
// rule book refuses at the moment of the release (the location filled during the place)
// keeps the thing in hand and fails in the same words.
#include <gtest/gtest.h>

#include <cmath>

#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/sim/scene.hpp"
#include "rtamp/sim/session.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

using Kind = world::Intervention::Kind;

// The 3-block layout with r1 full (capacity 3, holding o1..o3) and r2 of capacity 1.
world::Scenario tight() {
  world::Scenario s = testing::three_block();
  s.regions[0].capacity = 3;
  s.regions[1].capacity = 1;
  return s;
}

world::Intervention add(const std::string& name, const std::string& where) {
  world::Intervention iv;
  iv.kind = Kind::Add;
  iv.subject = name;
  iv.cls = "block";
  iv.location = where;
  return iv;
}

world::Intervention relocate(const std::string& thing, const std::string& where) {
  world::Intervention iv;
  iv.kind = Kind::Relocate;
  iv.subject = thing;
  iv.location = where;
  return iv;
}

std::string perceived(Session& s, const std::string& n) {
  Percept p = s.perception().observe();
  const Observation* o = p.find(n);
  return o ? o->location : "absent";
}

TEST(SimSpaceRules, PersonRefusesWhatTheSymbolicWorldRefusesInItsWords) {
  const world::Scenario sc = tight();
  Session mj(sc);
  mj.sim().step(50);
  exec::SymbolicWorld sym(sc);
  // In order: into full r1 (refused), o1 to r2 (applied), o2 to full r2 (refused),
  // o3 into o2, not a location (refused), a new block into full r2 (refused).
  const std::vector<world::Intervention> ivs{add("o9", "r1"), relocate("o1", "r2"), relocate("o2", "r2"),
                                             relocate("o3", "o2"), add("o8", "r2")};
  const std::vector<bool> expected{false, true, false, false, false};
  for (std::size_t k = 0; k < ivs.size(); ++k) {
    const OperatorEvent m = mj.op().apply(ivs[k]);
    const exec::WorldEvent y = sym.apply(ivs[k]);
    EXPECT_EQ(m.applied, expected[k]) << k << ": " << m.detail;
    EXPECT_EQ(y.applied, expected[k]) << k << ": " << y.detail;
    if (!expected[k]) {
      EXPECT_EQ(m.detail, y.detail) << k;
    }
  }
  EXPECT_EQ(mj.op().history()[0].detail, "r1 has no room (capacity 3)");
  EXPECT_EQ(mj.op().history()[2].detail, "r2 has no room (capacity 1)");
  mj.sim().step(200);
  EXPECT_EQ(perceived(mj, "o9"), "absent");
  EXPECT_EQ(perceived(mj, "o1"), "r2");
  EXPECT_EQ(perceived(mj, "o2"), "r1");
}

TEST(SimSpaceRules, ArmDoesNotPlaceIntoAFullLocation) {
  const world::Scenario sc = tight();
  Session s(sc);
  s.sim().step(50);
  ASSERT_TRUE(s.op().apply(relocate("o1", "r2")).applied);
  s.sim().step(200);
  const ActionResult r = s.execute(parse_actions("move o2 r2").front());
  EXPECT_EQ(r.status, Status::Failure);
  EXPECT_EQ(r.reason, "cannot place o2: r2 has no room (capacity 1)");
  // The same question the skill runner asks, answered by the rule book directly.
  EXPECT_EQ(space_refusal(s.sim(), "o2", {{0.04, 0.04, 0.04}, false}, "r2", {}), "r2 has no room (capacity 1)");
  EXPECT_EQ(space_refusal(s.sim(), "o2", {{0.04, 0.04, 0.04}, false}, "r3", {}), "");
}

TEST(SimSpaceRules, AReleaseTheRuleBookRefusesKeepsTheThingInHand) {
  // r2 (capacity 2) holds o2; the arm carries o1 there, and while the place runs a person
  // adds a block into r2. At the release the rule book says no: the arm keeps o1, backs
  // up, and the place fails in the symbolic world's words.
  world::Scenario sc = testing::three_block();
  sc.regions[1].capacity = 2;
  Session s(sc);
  s.sim().step(50);
  ASSERT_TRUE(s.op().apply(relocate("o2", "r2")).applied);
  s.sim().step(200);
  bool added = false;
  std::string refused_then;
  const ActionResult r = s.skills().move("o1", "r2", [&] {
    const Controller& c = s.controller();
    if (added || c.plan().skill != "place" || c.elapsed() < 0.2) return;
    const OperatorEvent e = s.op().apply(add("x1", "r2"));
    ASSERT_TRUE(e.applied) << e.detail;
    added = true;
    refused_then = space_refusal(s.sim(), "o1", {{0.04, 0.04, 0.04}, false}, "r2", {s.sim().find("o1")});
  });
  ASSERT_TRUE(added);
  EXPECT_EQ(refused_then, "r2 has no room (capacity 2)");
  EXPECT_EQ(r.status, Status::Failure);
  EXPECT_EQ(r.reason, "cannot place o1: r2 has no room (capacity 2)");
  EXPECT_EQ(s.sim().held(), s.sim().find("o1"));  // kept, not let go of over r2
  s.sim().step(200);
  EXPECT_EQ(perceived(s, "o1"), "hand");
  EXPECT_EQ(perceived(s, "o2"), "r2");
  EXPECT_EQ(perceived(s, "x1"), "r2");
  // Put back where it came from: r1 has room, and the release there is let go.
  ASSERT_TRUE(s.skills().start_place("r1"));
  EXPECT_EQ(s.skills().run_controller({}), Status::Success) << s.controller().reason();
  s.sim().step(200);
  EXPECT_EQ(s.sim().held(), -1);
  EXPECT_EQ(perceived(s, "o1"), "r1");
}

// The gap between two footprints: the larger of their x and y separations.
double clearance(const Eigen::Vector3d& a, const world::Vec3& sa, const Eigen::Vector3d& b, const world::Vec3& sb) {
  const double gx = std::abs(a.x() - b.x()) - (sa[0] + sb[0]) / 2;
  const double gy = std::abs(a.y() - b.y()) - (sa[1] + sb[1]) / 2;
  return std::max(gx, gy);
}

TEST(SimSpaceRules, PersonKeepsTheArmsClearance) {
  // r2 empty and large: the person adds blocks until it finds no spot; every pair of
  // footprints there keeps the arm's clearance, and the arm then picks each added block
  // without pushing another out of r2.
  world::Scenario sc = testing::three_block();
  Session s(sc);
  s.sim().step(50);
  std::vector<std::string> added;
  for (int k = 0; k < 4; ++k) {
    const OperatorEvent e = s.op().apply(add("a" + std::to_string(k), "r2"));
    if (!e.applied) break;
    added.push_back("a" + std::to_string(k));
  }
  ASSERT_GE(added.size(), 3u);  // 24 cm holds a 3 x 3 grid of 4 cm blocks at 3.5 cm
  for (std::size_t i = 0; i < added.size(); ++i)
    for (std::size_t j = i + 1; j < added.size(); ++j) {
      const int a = s.sim().find(added[i]), b = s.sim().find(added[j]);
      EXPECT_GE(clearance(s.sim().position(a), s.sim().thing(a).size, s.sim().position(b), s.sim().thing(b).size),
                world::kPlaceGap - 1e-9)
          << added[i] << " " << added[j];
    }
  s.sim().step(200);
  for (const std::string& n : added) {
    const ActionResult r = s.execute(parse_actions("move " + n + " r3").front());
    ASSERT_EQ(r.status, Status::Success) << n << ": " << r.reason;
    s.sim().step(200);
    EXPECT_EQ(perceived(s, n), "r3");
    bool moved = true;  // the ones moved so far are in r3, the others still in r2
    for (const std::string& other : added) {
      EXPECT_EQ(perceived(s, other), moved ? "r3" : "r2") << other << " after moving " << n;
      if (other == n) moved = false;
    }
  }
}

}  // namespace
}  // namespace rtamp::sim
