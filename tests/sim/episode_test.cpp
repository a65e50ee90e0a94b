// Behaviour of the simulated world on the built-in scenarios (world::load_scenario):
// every block picked and placed into every other location ends up there as perceived;
// a carried tray keeps its blocks; removed things are perceived gone, added ones
// appear; taking the object from the gripper makes the running skill fail cleanly;
// the same seed gives the same episode.
#include <gtest/gtest.h>

#include "rtamp/sim/session.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::sim {
namespace {

std::string perceived(Session& s, const std::string& n) {
  Percept p = s.perception().observe();
  const Observation* o = p.find(n);
  return o ? o->location : "absent";
}

TEST(SimEpisode, EveryBlockToEveryLocation) {
  for (const char* name : {"3-block", "3-block-tray"}) {
    const world::Scenario sc = world::load_scenario(name);
    std::vector<std::string> locations;
    for (const auto& r : sc.regions) locations.push_back(r.name);
    for (const auto& c : sc.containers) locations.push_back(c.name);
    for (const auto& o : sc.objects) {
      for (const auto& l : locations) {
        Session s(sc);
        s.sim().step(50);
        if (perceived(s, o.name) == l) continue;
        ActionResult r = s.execute(parse_actions("move " + o.name + " " + l).front());
        EXPECT_EQ(r.status, Status::Success) << name << ": move " << o.name << " " << l << ": " << r.reason;
        s.sim().step(250);
        EXPECT_EQ(perceived(s, o.name), l) << name << ": move " << o.name << " " << l;
        EXPECT_EQ(s.sim().warnings().total(), 0);
        // The skills' motions stay inside the UR5's published effort limits.
        EXPECT_EQ(s.sim().torque_limited_steps(), 0) << name << ": move " << o.name << " " << l;
      }
    }
  }
}

TEST(SimEpisode, TrayCarriesItsBlocks) {
  Session s(world::load_scenario("3-block-tray"));
  auto rep = s.run(parse_actions("move o1 r3; move o2 r3; move r3 r2; wait 0.5"));
  for (const auto& r : rep.actions) ASSERT_EQ(r.status, Status::Success) << r.action << ": " << r.reason;
  EXPECT_EQ(perceived(s, "r3"), "r2");
  EXPECT_EQ(perceived(s, "o1"), "r3");
  EXPECT_EQ(perceived(s, "o2"), "r3");
  EXPECT_EQ(perceived(s, "o3"), "r1");
  EXPECT_EQ(s.sim().torque_limited_steps(), 0);  // a loaded tray too: inside the effort limits
}

TEST(SimEpisode, RemovedGoneAddedAppears) {
  Session s(world::load_scenario("3-block"));
  world::Intervention rm;
  rm.kind = world::Intervention::Kind::Remove;
  rm.subject = "o2";
  EXPECT_TRUE(s.op().apply(rm).applied);
  world::Intervention add;
  add.kind = world::Intervention::Kind::Add;
  add.subject = "o9";
  add.cls = "block";
  add.location = "r2";
  OperatorEvent e = s.op().apply(add);
  EXPECT_TRUE(e.applied) << e.detail;
  s.sim().step(200);
  EXPECT_EQ(perceived(s, "o2"), "absent");
  EXPECT_EQ(perceived(s, "o9"), "r2");
  // The added block can be handled like any other.
  ActionResult r = s.execute(parse_actions("move o9 r1").front());
  EXPECT_EQ(r.status, Status::Success) << r.reason;
  s.sim().step(200);
  EXPECT_EQ(perceived(s, "o9"), "r1");
  // Relocation never stacks: every present block keeps its own footprint.
  world::Intervention mv;
  mv.kind = world::Intervention::Kind::Relocate;
  mv.subject = "o1";
  mv.location = "r1";
  EXPECT_TRUE(s.op().apply(mv).applied);
  s.sim().step(200);
  Percept p = s.perception().observe();
  for (const auto& a : p.things) {
    for (const auto& b : p.things) {
      if (&a == &b || a.container || b.container) continue;
      EXPECT_GT(std::hypot(a.position[0] - b.position[0], a.position[1] - b.position[1]), 0.04)
          << a.name << " " << b.name;
    }
  }
}

TEST(SimEpisode, TakingTheObjectFailsTheSkillCleanly) {
  Session s(world::load_scenario("3-block"));
  ASSERT_EQ(s.execute(parse_actions("pick o1").front()).status, Status::Success);
  ASSERT_TRUE(s.skills().start_place("r2"));
  for (int k = 0; k < 300; ++k) s.controller().step();
  ASSERT_EQ(s.controller().status(), Status::Running);
  world::Intervention take;
  take.kind = world::Intervention::Kind::TakeFromGripper;
  take.location = "r1";
  EXPECT_TRUE(s.op().apply(take).applied);
  Status st = s.skills().run_controller({});
  EXPECT_EQ(st, Status::Failure);
  EXPECT_NE(s.controller().reason().find("taken"), std::string::npos) << s.controller().reason();
  EXPECT_EQ(s.sim().held(), -1);
  s.sim().step(300);
  EXPECT_EQ(perceived(s, "o1"), "r1");
  // The robot can go on: picking o1 again works.
  EXPECT_EQ(s.execute(parse_actions("move o1 r2").front()).status, Status::Success);
}

TEST(SimEpisode, TakingToAPlaceWithNoRoomIsRefusedAndTheThingStaysHeld) {
  Session s(world::load_scenario("3-block"));
  ASSERT_EQ(s.execute(parse_actions("pick o1").front()).status, Status::Success);
  const int o1 = s.sim().find("o1");
  ASSERT_EQ(s.sim().held(), o1);
  // On top of o2: no room there, so the person does not take it (it used to vanish).
  const Eigen::Vector3d o2 = s.sim().position(s.sim().find("o2"));
  world::Intervention take;
  take.kind = world::Intervention::Kind::TakeFromGripper;
  take.position = world::Vec3{o2.x(), o2.y(), o2.z()};
  const OperatorEvent e = s.op().apply(take);
  EXPECT_FALSE(e.applied);
  EXPECT_NE(e.detail.find("stays in the gripper"), std::string::npos) << e.detail;
  EXPECT_EQ(s.sim().held(), o1);
  EXPECT_TRUE(s.sim().thing(o1).present);
  // And the robot can still put it down.
  EXPECT_EQ(s.execute(parse_actions("place r2").front()).status, Status::Success);
  s.sim().step(300);
  EXPECT_EQ(perceived(s, "o1"), "r2");
}

TEST(SimEpisode, SameSeedSameEpisode) {
  auto run = [](std::uint64_t seed) {
    SessionOptions o;
    o.seed = seed;
    o.person.rate = 0.3;
    o.perception.position_sigma = 0.003;
    Session s(world::load_scenario("3-block-tray"), o);
    auto rep = s.run(parse_actions("move o1 r3; move o2 r2; wait 2"));
    std::vector<double> sig;
    for (const auto& r : rep.actions) sig.push_back(r.duration), sig.push_back(r.cost);
    for (const auto& t : rep.final_percept.things)
      sig.insert(sig.end(), t.position.begin(), t.position.end());
    sig.push_back(static_cast<double>(rep.interventions.size()));
    return sig;
  };
  const auto a = run(5), b = run(5);
  EXPECT_EQ(a, b);
}

TEST(SimEpisode, ActionListErrorsHaveColumns) {
  try {
    parse_actions("move o1 r2; fly o2");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().column, 13);
  }
  EXPECT_THROW(parse_actions("move o1"), Error);
  EXPECT_THROW(parse_actions("wait -1"), Error);
  EXPECT_EQ(parse_actions(" ; move o1 r2 ;; pick o3").size(), 2u);
}

}  // namespace
}  // namespace rtamp::sim
