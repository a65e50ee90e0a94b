// sim::Session checks an action list before anything moves (the C++
// API refuses what `rtamp sim --do` refuses, with the same words): run()
// checks every action of the list first, execute() its one action, against
// the names of the running simulation; a bad list leaves the world exactly as
// it was (no simulated time, nothing held, every thing where it was). A
// random operator's rate must be finite and >= 0.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rtamp/sim/session.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::sim {
namespace {

// Where every thing is, and what the gripper holds, and the time.
struct Snapshot {
  std::vector<double> positions;
  int held = -1;
  double time = 0;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot(const Session& s) {
  Snapshot out;
  for (int i = 0; i < static_cast<int>(s.sim().things().size()); ++i) {
    const Eigen::Vector3d p = s.sim().position(i);
    out.positions.insert(out.positions.end(), {p.x(), p.y(), p.z()});
  }
  out.held = s.sim().held();
  out.time = s.sim().time();
  return out;
}

struct Refusal {
  std::string list;
  std::string where;  // "actions:1:COL"
  std::string what;   // in the message
};

TEST(SessionCheck, ABadListMovesNothing) {
  const world::Scenario sc = world::load_scenario("3-block-tray");
  const std::vector<Refusal> cases = {
      {"move o1 r2; move o1 r9", "actions:1:21", "unknown location 'r9'"},
      {"move o1 r2; move o9 r1", "actions:1:18", "unknown object or container 'o9'"},
      {"pick o1; place r2; move r1 r2", "actions:1:25", "'r1' is a region"},
      {"move o1 o2", "actions:1:9", "'o2' is an object, not a location"},
      {"move r3 r3", "actions:1:9", "cannot be placed in itself"},
      {"move o1 r3; move r3 r3x", "actions:1:21", "did you mean 'r3'"},
      {"pick o1; place blocks", "actions:1:16", "unknown location 'blocks'"},
  };
  for (const Refusal& c : cases) {
    Session s(sc);
    const Snapshot before = snapshot(s);
    try {
      (void)s.run(parse_actions(c.list));
      ADD_FAILURE() << c.list << ": accepted";
    } catch (const Error& e) {
      EXPECT_EQ(format_location(e.where()), c.where + ": ") << c.list << ": " << e.what();
      EXPECT_NE(e.message().find(c.what), std::string::npos) << c.list << ": " << e.what();
    }
    EXPECT_EQ(snapshot(s), before) << c.list << ": something moved";
  }
}

TEST(SessionCheck, ExecuteChecksItsAction) {
  Session s(world::load_scenario("3-block"));
  const Snapshot before = snapshot(s);
  try {
    (void)s.execute(parse_actions("move o1 r9").front());
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(format_location(e.where()), "action:1:9: ");
    EXPECT_NE(e.message().find("unknown location 'r9'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(snapshot(s), before);
  EXPECT_EQ(s.sim().held(), -1);  // o1 was not picked up
}

TEST(SessionCheck, ActionsBuiltInCodeAreCheckedToo) {
  Session s(world::load_scenario("3-block"));
  const Snapshot before = snapshot(s);
  SimAction wait;
  wait.kind = SimAction::Kind::Wait;
  for (double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity(), 1e9}) {
    wait.seconds = bad;
    EXPECT_THROW((void)s.run({wait}), Error) << bad;
    EXPECT_THROW((void)s.execute(wait), Error) << bad;
  }
  SimAction move;
  move.thing = "o1";
  move.location = "r7";  // no text: the check writes the action out
  try {
    (void)s.run({move});
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(format_location(e.where()), "actions:1:9: ") << e.what();
  }
  EXPECT_EQ(snapshot(s), before);
}

TEST(SessionCheck, ARandomOperatorRateOutOfRangeIsRefused) {
  const world::Scenario sc = world::load_scenario("3-block");
  for (double bad : {std::nan(""), -1.0, std::numeric_limits<double>::infinity()}) {
    SessionOptions o;
    o.person.rate = bad;
    try {
      Session s(sc, o);
      ADD_FAILURE() << bad << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("the rate of random interventions"), std::string::npos) << e.what();
    }
  }
}

TEST(SessionCheck, NamesAddedSinceTheStartAreKnown) {
  Session s(world::load_scenario("3-block"));
  world::Intervention add;
  add.kind = world::Intervention::Kind::Add;
  add.subject = "o9";
  add.cls = "block";
  add.location = "r2";
  ASSERT_TRUE(s.op().apply(add).applied);
  s.sim().step(100);
  const SessionReport rep = s.run(parse_actions("move o9 r1"));
  ASSERT_EQ(rep.actions.size(), 1u);
  EXPECT_EQ(rep.actions[0].status, Status::Success) << rep.actions[0].reason;
  // A good list runs as before the check: every action, in order.
  const SessionReport two = s.run(parse_actions("pick o1; place r2; wait 0.1"));
  ASSERT_EQ(two.actions.size(), 3u);
  for (const ActionResult& r : two.actions) EXPECT_EQ(r.status, Status::Success) << r.action << ": " << r.reason;
}

}  // namespace
}  // namespace rtamp::sim
