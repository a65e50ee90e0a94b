// SymbolicWorld (exec/symbolic_world.hpp): the timing model, observed
// locations along a move, every intervention in every phase, failures, halts,
// scripted and random interventions, the footprint rules (what fits where, and
// agreement with task::System on them), invariants and determinism.
#include "rtamp/exec/symbolic_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

using Kind = world::Intervention::Kind;

// r1 (cap 3): o1 and tray t1 (cap 2) holding o2; r2 (cap 3): o3; r3 (cap 1): o4 (full); r4 (cap 2): empty.
// The tray (24 x 16 cm) fits r1, r2 and r4 (r4: room for one such tray), not r3 (20 x 20 cm).
constexpr const char* kTiny = R"(
name: tiny
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.30, 0], size: [0.36, 0.36], capacity: 3}
  - {name: r2, center: [0.40, -0.30, 0], size: [0.36, 0.36], capacity: 3}
  - {name: r3, center: [0.70, 0.00, 0], size: [0.20, 0.20], capacity: 1}
  - {name: r4, center: [0.72, 0.40, 0], size: [0.24, 0.24], capacity: 2}
containers:
  - {name: t1, class: tray, position: [0.40, 0.25, 0], size: [0.24, 0.16, 0.03], capacity: 2}
objects:
  - {name: o1, class: block, position: [0.40, 0.42, 0]}
  - {name: o2, class: block, position: [0.40, 0.25, 0.01]}
  - {name: o3, class: block, position: [0.40, -0.30, 0]}
  - {name: o4, class: block, position: [0.70, 0.00, 0]}
propositions: {done: "o1 in r2"}
task: "F done"
)";

world::Scenario tiny() { return world::parse_scenario(kTiny, "tiny.yaml"); }

Move move(const std::string& thing, const std::string& from, const std::string& to) {
  return Move{"move(" + thing + ", " + to + ")", thing, from, to};
}

std::string loc(const SymbolicWorld& w, const std::string& thing) {
  const std::string* l = w.truth().location_of(thing);
  return l ? *l : "";
}

double dist(const world::Vec3& a, const world::Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// Advances to the end of the current phase.
void step_phase(SymbolicWorld& w) { w.advance(w.phase_end() - w.time()); }

void run_until_idle(SymbolicWorld& w) {
  for (int i = 0; i < 100 && w.phase() != Phase::Idle; ++i) {
    step_phase(w);
    ASSERT_EQ(w.check_invariants(), "");
  }
  ASSERT_EQ(w.phase(), Phase::Idle);
}

// Advances into the middle of phase `p` of the running move.
void to_middle_of(SymbolicWorld& w, Phase p) {
  for (int i = 0; i < 10 && w.phase() != p; ++i) step_phase(w);
  ASSERT_EQ(w.phase(), p);
  w.advance((w.phase_end() - w.time()) / 2);
  ASSERT_EQ(w.phase(), p);
}

world::Intervention iv(Kind k, std::string subject = "", std::string location = "", std::string cls = "") {
  world::Intervention i;
  i.kind = k;
  i.subject = std::move(subject);
  i.location = std::move(location);
  i.cls = std::move(cls);
  return i;
}

// When the middle (or the end) of phase `p` of move(o1, r1 -> r2) in tiny() comes.
double time_in(Phase p, bool end) {
  SymbolicWorld probe(tiny());
  probe.start(move("o1", "r1", "r2"));
  to_middle_of(probe, p);
  return end ? probe.phase_end() : probe.time();
}

// A symbolic world with a person acting on it (world/person.hpp, through exec::PersonWorld).
struct Acted {
  SymbolicWorld w;
  world::Person person;
  PersonWorld pw;
  Acted(const world::Scenario& s, world::PersonOptions po, SymbolicWorldOptions wo = {})
      : w(s, std::move(wo)), person(s, std::move(po)), pw(w, person) {}
};

world::PersonOptions script(std::vector<world::Intervention> what) {
  world::PersonOptions o;
  o.script = std::move(what);
  return o;
}

// tiny() with `what` scripted at time `t`, running move(o1, r1 -> r2).
std::unique_ptr<Acted> moving_o1_with(world::Intervention what, double t) {
  what.time = t;
  auto a = std::make_unique<Acted>(tiny(), script({what}));
  a->w.start(move("o1", "r1", "r2"));
  return a;
}

// ---------------------------------------------------------------- timing

TEST(SymbolicWorld, PhaseTimingsAndObservedLocationsAlongAMove) {
  const auto s = world::load_scenario("3-block-tray");
  SymbolicWorld w(s);
  const world::Vec3 home{0, 0, 0.5}, r1{0.40, 0.32, 0}, r2{0.40, -0.32, 0};
  EXPECT_EQ(w.hand(), "");
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Idle);
  EXPECT_EQ(w.next_event_time(), std::numeric_limits<double>::infinity());
  w.start(move("o1", "r1", "r2"));
  ASSERT_EQ(w.poll(nullptr), MoveStatus::Running);

  struct Expect {
    Phase phase;
    double duration;
    const char* observed;  // o1's location during the phase
  };
  const std::vector<Expect> phases{{Phase::Approach, 0.5 + dist(home, r1) / 0.25, "r1"},
                                   {Phase::Grasp, 0.5, "r1"},
                                   {Phase::Carry, 0.5 + dist(r1, r2) / 0.25, kInHand},
                                   {Phase::Place, 0.5, kInHand},
                                   {Phase::Retreat, 0.5, "r2"}};
  double t = 0;
  for (const auto& e : phases) {
    SCOPED_TRACE(to_string(e.phase));
    ASSERT_EQ(w.phase(), e.phase);
    EXPECT_NEAR(w.phase_end(), t + e.duration, 1e-12);
    EXPECT_NEAR(w.next_event_time(), t + e.duration, 1e-12);
    w.advance(e.duration * 0.99);
    EXPECT_EQ(w.phase(), e.phase);
    EXPECT_EQ(*w.observe().location_of("o1"), e.observed);
    EXPECT_EQ(w.poll(nullptr), MoveStatus::Running);
    EXPECT_EQ(w.check_invariants(), "");
    t += e.duration;
    w.advance(t - w.time());
  }
  EXPECT_EQ(w.phase(), Phase::Idle);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  EXPECT_EQ(loc(w, "o1"), "r2");
  EXPECT_EQ(w.hand(), "r2");
  EXPECT_NEAR(w.time(), t, 1e-12);

  // The next approach starts from r2; a tray move carries its contents.
  w.start(move("o2", "r1", "r3"));
  EXPECT_NEAR(w.phase_end() - w.time(), 0.5 + dist(r2, r1) / 0.25, 1e-12);
  run_until_idle(w);
  ASSERT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  w.start(move("r3", "r1", "r2"));
  step_phase(w);
  step_phase(w);
  EXPECT_EQ(loc(w, "r3"), kInHand);
  EXPECT_EQ(loc(w, "o2"), "r3");
  run_until_idle(w);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  EXPECT_EQ(loc(w, "r3"), "r2");
  EXPECT_EQ(loc(w, "o2"), "r3");
}

TEST(SymbolicWorld, TimingOptionsAreUsed) {
  SymbolicWorldOptions o;
  o.approach_base = 1;
  o.grasp = 2;
  o.carry_base = 3;
  o.place = 4;
  o.retreat = 5;
  o.speed = 1;
  SymbolicWorld w(tiny(), o);
  w.start(move("o1", "r1", "r2"));
  const world::Vec3 home{0, 0, 0.5}, r1{0.4, 0.3, 0}, r2{0.4, -0.3, 0};
  EXPECT_NEAR(w.phase_end(), 1 + dist(home, r1), 1e-12);
  run_until_idle(w);
  EXPECT_NEAR(w.time(), 1 + dist(home, r1) + 2 + 3 + dist(r1, r2) + 4 + 5, 1e-12);
}

TEST(SymbolicWorld, AdvanceProcessesEveryEventInOneCall) {
  SymbolicWorld w(tiny());
  w.start(move("o1", "r1", "r2"));
  w.advance(100);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  EXPECT_EQ(w.time(), 100);
  EXPECT_EQ(loc(w, "o1"), "r2");
}

TEST(SymbolicWorld, StartFailsAtOnceOnBadMoves) {
  struct Case {
    Move m;
    const char* why;
  };
  const std::vector<Case> cases{{move("o9", "r1", "r2"), "not in the world"},
                                {move("o1", "r2", "r3"), "is in r1, not in r2"},
                                {move("o1", "r1", "r9"), "unknown location r9"},
                                {move("t1", "r1", "t1"), "cannot go into itself"},
                                {move("t1", "r1", "t1x"), "unknown location"}};
  for (const auto& c : cases) {
    SymbolicWorld w(tiny());
    w.start(c.m);
    std::string why;
    EXPECT_EQ(w.poll(&why), MoveStatus::Failed) << c.m.action;
    EXPECT_NE(why.find(c.why), std::string::npos) << why;
    EXPECT_EQ(w.phase(), Phase::Idle);
    EXPECT_FALSE(w.busy());
    EXPECT_EQ(w.truth(), SymbolicWorld(tiny()).truth());
  }
  Acted a(tiny(), script({iv(Kind::AddContainer, "t2", "r4")}));  // at t = 0: applied at once
  SymbolicWorld& w = a.w;
  w.start(move("t1", "r1", "t2"));
  std::string why;
  EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
  EXPECT_NE(why.find("only goes into a region"), std::string::npos) << why;
  w.start(move("o1", "", "r2"));  // no `from`: picked wherever it is
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Running);
  EXPECT_THROW(w.start(move("o3", "r2", "r1")), std::logic_error);
}

// ---------------------------------------------------------------- interventions in every phase

struct Outcome {
  bool applied;
  MoveStatus status;  // of the move, once the world is idle
  const char* why;    // substring of the reason when Failed
  const char* o1;     // where o1 ends ("" = gone)
};

struct InterventionCase {
  const char* name;
  std::vector<world::Intervention> what;    // applied in order; `applied` refers to the last one
  Outcome before_grasp;                     // in Approach or Grasp
  Outcome held;                             // in Carry or Place
  Outcome placed;                           // in Retreat
  std::map<std::string, std::string> also;  // other things' final locations ("" = gone)
};

std::vector<InterventionCase> intervention_cases() {
  using S = MoveStatus;
  const Outcome ok{true, S::Succeeded, "", "r2"};
  const Outcome refused_ok{false, S::Succeeded, "", "r2"};
  world::Intervention by_position = iv(Kind::Relocate, "o1");
  by_position.position = world::Vec3{0.72, 0.40, 0};
  return {
      {"relocate o1 to r4",
       {iv(Kind::Relocate, "o1", "r4")},
       {true, S::Failed, "no longer in r1", "r4"},
       {true, S::Failed, "taken from the gripper", "r4"},
       {true, S::Succeeded, "", "r4"},
       {}},
      {"relocate o1 by position (r4)",
       {by_position},
       {true, S::Failed, "no longer in r1", "r4"},
       {true, S::Failed, "taken from the gripper", "r4"},
       {true, S::Succeeded, "", "r4"},
       {}},
      {"relocate o1 into full r3",
       {iv(Kind::Relocate, "o1", "r3")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"o4", "r3"}}},
      {"relocate o1 into tray t1",
       {iv(Kind::Relocate, "o1", "t1")},
       {true, S::Failed, "no longer in r1", "t1"},
       {true, S::Failed, "taken from the gripper", "t1"},
       {true, S::Succeeded, "", "t1"},
       {}},
      {"relocate tray t1 to r4 (carries o2)",
       {iv(Kind::Relocate, "t1", "r4")},
       ok,
       ok,
       ok,
       {{"t1", "r4"}, {"o2", "t1"}}},
      {"relocate tray into itself",
       {iv(Kind::Relocate, "t1", "t1")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"t1", "r1"}}},
      {"relocate unknown thing", {iv(Kind::Relocate, "o9", "r4")}, refused_ok, refused_ok, refused_ok, {}},
      {"relocate to unknown location",
       {iv(Kind::Relocate, "o3", "r9")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"o3", "r2"}}},
      {"remove o1",
       {iv(Kind::Remove, "o1")},
       {true, S::Failed, "gone", ""},
       {true, S::Failed, "taken from the gripper", ""},
       {true, S::Succeeded, "", ""},
       {}},
      {"remove o3", {iv(Kind::Remove, "o3")}, ok, ok, ok, {{"o3", ""}}},
      {"remove a container with remove",
       {iv(Kind::Remove, "t1")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"t1", "r1"}}},
      {"add x to r2", {iv(Kind::Add, "x", "r2", "block")}, ok, ok, ok, {{"x", "r2"}}},
      {"add with a taken name",
       {iv(Kind::Add, "o3", "r4")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"o3", "r2"}}},
      {"add with a container class",
       {iv(Kind::Add, "x", "r4", "tray")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"x", ""}}},
      {"add into full r3", {iv(Kind::Add, "x", "r3")}, refused_ok, refused_ok, refused_ok, {{"x", ""}}},
      {"fill r2 (two adds)",
       {iv(Kind::Add, "x", "r2"), iv(Kind::Add, "y", "r2")},
       {true, S::Failed, "r2 has no room", "r1"},
       {true, S::Failed, "r2 has no room", "r1"},
       {false, S::Succeeded, "", "r2"},
       {}},
      {"add container t2 to r4", {iv(Kind::AddContainer, "t2", "r4")}, ok, ok, ok, {{"t2", "r4"}}},
      {"add container into a container",
       {iv(Kind::AddContainer, "t2", "t1")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"t2", ""}}},
      {"remove container t1 (o2 drops into r1)",
       {iv(Kind::RemoveContainer, "t1")},
       ok,
       ok,
       ok,
       {{"t1", ""}, {"o2", "r1"}}},
      {"remove container of an object",
       {iv(Kind::RemoveContainer, "o3")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"o3", "r2"}}},
      {"take from gripper (remove)",
       {iv(Kind::TakeFromGripper)},
       refused_ok,
       {true, S::Failed, "taken from the gripper", ""},
       refused_ok,
       {}},
      {"take from gripper to r4",
       {iv(Kind::TakeFromGripper, "", "r4")},
       refused_ok,
       {true, S::Failed, "taken from the gripper", "r4"},
       refused_ok,
       {}},
      {"take from gripper to full r3",
       {iv(Kind::TakeFromGripper, "", "r3")},
       refused_ok,
       refused_ok,
       refused_ok,
       {{"o4", "r3"}}},
  };
}

TEST(SymbolicWorld, EveryInterventionInEveryPhase) {
  for (const auto& c : intervention_cases()) {
    for (Phase p : {Phase::Approach, Phase::Grasp, Phase::Carry, Phase::Place, Phase::Retreat}) {
      SCOPED_TRACE(std::string(c.name) + " in " + to_string(p));
      SymbolicWorld w(tiny());
      w.start(move("o1", "r1", "r2"));
      to_middle_of(w, p);
      const double t = w.time();
      WorldEvent last;
      for (const auto& i : c.what) last = w.apply(i);
      const Outcome& e = p == Phase::Carry || p == Phase::Place ? c.held
                         : p == Phase::Retreat                  ? c.placed
                                                                : c.before_grasp;
      EXPECT_EQ(last.applied, e.applied) << last.detail;
      EXPECT_FALSE(last.detail.empty());
      EXPECT_EQ(last.time, t);
      EXPECT_EQ(w.check_invariants(), "");
      const auto events = w.take_events();
      EXPECT_EQ(events.size(), c.what.size());
      EXPECT_TRUE(w.take_events().empty());
      EXPECT_EQ(w.history().size(), c.what.size());
      if (!e.applied) {  // a refused intervention changes nothing
        const std::string* o1 = w.truth().location_of("o1");
        ASSERT_TRUE(o1);
        EXPECT_EQ(*o1, p == Phase::Carry || p == Phase::Place ? kInHand : p == Phase::Retreat ? "r2" : "r1");
      }
      run_until_idle(w);
      std::string why;
      EXPECT_EQ(w.poll(&why), e.status) << why;
      if (e.status == MoveStatus::Failed) {
        EXPECT_NE(why.find(e.why), std::string::npos) << why;
      }
      EXPECT_EQ(loc(w, "o1"), e.o1);
      for (const auto& [thing, where] : c.also) EXPECT_EQ(loc(w, thing), where) << thing;
      EXPECT_FALSE(w.busy());
      EXPECT_EQ(w.check_invariants(), "");
    }
  }
}

TEST(SymbolicWorld, RemovedContainerSpillsIntoTheClosestRegionWithRoom) {
  SymbolicWorld w(tiny());
  ASSERT_TRUE(w.apply(iv(Kind::Add, "o5", "t1")).applied);  // t1 full: o2, o5
  ASSERT_TRUE(w.apply(iv(Kind::Add, "x", "r1")).applied);   // r1 full: o1, t1, x
  const WorldEvent e = w.apply(iv(Kind::RemoveContainer, "t1"));
  ASSERT_TRUE(e.applied);
  EXPECT_EQ(loc(w, "o2"), "r1");  // the freed place
  EXPECT_EQ(loc(w, "o5"), "r4");  // r4 is 0.34 m from r1, r3 is full, r2 is 0.6 m
  EXPECT_NE(e.detail.find("r1 has no room"), std::string::npos) << e.detail;
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, PlaceIntoARemovedTrayPutsTheThingBack) {
  SymbolicWorld w(tiny());
  w.start(move("o1", "r1", "t1"));
  to_middle_of(w, Phase::Carry);
  ASSERT_TRUE(w.apply(iv(Kind::RemoveContainer, "t1")).applied);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Running);
  step_phase(w);  // carry ends
  step_phase(w);  // place fails: return begins
  EXPECT_EQ(w.phase(), Phase::Return);
  EXPECT_EQ(loc(w, "o1"), kInHand);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Running);
  run_until_idle(w);
  std::string why;
  EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
  EXPECT_NE(why.find("t1"), std::string::npos) << why;
  EXPECT_EQ(loc(w, "o1"), "r1");
  EXPECT_EQ(loc(w, "o2"), "r1");
  EXPECT_EQ(w.hand(), "r1");
}

TEST(SymbolicWorld, RelocatingTheHeldTrayKeepsItsContents) {
  SymbolicWorld w(tiny());
  w.start(move("t1", "r1", "r2"));
  to_middle_of(w, Phase::Carry);
  EXPECT_EQ(loc(w, "t1"), kInHand);
  EXPECT_EQ(loc(w, "o2"), "t1");
  EXPECT_FALSE(w.apply(iv(Kind::Relocate, "o3", "t1")).applied);  // the tray is in the gripper
  ASSERT_TRUE(w.apply(iv(Kind::TakeFromGripper, "", "r4")).applied);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Failed);
  EXPECT_EQ(loc(w, "t1"), "r4");
  EXPECT_EQ(loc(w, "o2"), "t1");
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, RemovingTheHeldTraySpillsItsContents) {
  SymbolicWorld w(tiny());
  w.start(move("t1", "r1", "r2"));
  to_middle_of(w, Phase::Place);  // the hand is over r2
  const WorldEvent e = w.apply(iv(Kind::TakeFromGripper));
  ASSERT_TRUE(e.applied);
  EXPECT_EQ(e.what.subject, "t1");
  EXPECT_EQ(loc(w, "t1"), "");
  EXPECT_EQ(loc(w, "o2"), "r2");
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Failed);
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, APositionOutsideEveryLocationIsNone) {
  SymbolicWorld w(tiny());
  world::Intervention off = iv(Kind::Relocate, "o3");
  off.position = world::Vec3{0.0, 0.6, 0};  // on the table (it ends at y = 0.67), in no region
  ASSERT_TRUE(w.apply(off).applied);
  EXPECT_EQ(loc(w, "o3"), world::kNoLocation);
  EXPECT_FALSE(w.apply(iv(Kind::Relocate, "o4", world::kNoLocation)).applied);  // only by position
  EXPECT_EQ(w.check_invariants(), "");
  w.start(move("o3", world::kNoLocation, "r2"));
  const world::Vec3 home{0, 0, 0.5}, at{0.0, 0.6, 0};
  EXPECT_NEAR(w.phase_end(), 0.5 + dist(home, at) / 0.25, 1e-12);
  run_until_idle(w);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  EXPECT_EQ(loc(w, "o3"), "r2");
  EXPECT_EQ(w.check_invariants(), "");
}

// A position off the table top (world/table.hpp) is refused: the thing would fall to the floor.
TEST(SymbolicWorld, APositionOffTheTableIsRefused) {
  SymbolicWorld w(tiny());
  for (const world::Vec3& p : {world::Vec3{3.0, 0.0, 0}, world::Vec3{0.4, -2.0, 0}, world::Vec3{std::nan(""), 0, 0}}) {
    world::Intervention off = iv(Kind::Relocate, "o3");
    off.position = p;
    const WorldEvent e = w.apply(off);
    EXPECT_FALSE(e.applied);
    EXPECT_NE(e.detail.find("is off the table"), std::string::npos) << e.detail;
    world::Intervention add = iv(Kind::Add, "o9");
    add.cls = "block";
    add.position = p;
    EXPECT_FALSE(w.apply(add).applied);
  }
  EXPECT_NE(loc(w, "o3"), world::kNoLocation);
  EXPECT_EQ(w.observe().things.count("o9"), 0u);
}

TEST(SymbolicWorld, MovingTheSourceTrayBeforeTheGraspTakesTheThingFromItsNewPlace) {
  SymbolicWorld w(tiny());
  w.start(move("o2", "t1", "r2"));
  to_middle_of(w, Phase::Approach);
  ASSERT_TRUE(w.apply(iv(Kind::Relocate, "t1", "r4")).applied);
  run_until_idle(w);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);  // the location is the tray, wherever it stands
  EXPECT_EQ(loc(w, "o2"), "r2");
  EXPECT_EQ(loc(w, "t1"), "r4");
}

TEST(SymbolicWorld, AddedContainersGetTheCapacityOfTheirClass) {
  SymbolicWorld w(tiny());
  ASSERT_TRUE(w.apply(iv(Kind::AddContainer, "t2", "r4")).applied);
  ASSERT_TRUE(w.apply(iv(Kind::AddContainer, "b1", "r2", "box")).applied);
  EXPECT_EQ(w.capacity("t2"), 2);  // like t1
  EXPECT_EQ(w.capacity("b1"), 4);  // added_container_capacity
  EXPECT_EQ(w.capacity("r3"), 1);
  EXPECT_EQ(w.capacity("nowhere"), -1);
  EXPECT_FALSE(w.apply(iv(Kind::AddContainer, "t3", "r4")).applied);  // r4 (capacity 2) is full
  EXPECT_TRUE(w.truth().things.at("b1").container);
  EXPECT_EQ(w.truth().things.at("b1").cls, "box");
  // An added container is a location like any other.
  ASSERT_TRUE(w.apply(iv(Kind::Relocate, "o3", "t2")).applied);
  w.start(move("o1", "r1", "b1"));
  run_until_idle(w);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  EXPECT_EQ(loc(w, "o1"), "b1");
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, AnOverfullInitialPlacementIsAnError) {
  world::Scenario s;
  s.name = "overfull";
  world::Region r;
  r.name = "r1";
  r.center = {0.4, 0, 0};
  r.capacity = 1;
  s.regions = {r};
  for (const char* n : {"a", "b"}) {
    world::Object o;
    o.name = n;
    o.position = {0.4, 0, 0};
    s.objects.push_back(o);
  }
  EXPECT_THROW(SymbolicWorld{s}, Error);
}

TEST(SymbolicWorld, PositionsOfContainersFallInRegions) {
  SymbolicWorld w(tiny());
  world::Intervention stay = iv(Kind::Relocate, "t1");
  stay.position = world::Vec3{0.40, 0.25, 0};  // where t1 stands: the region r1, not t1 itself
  const WorldEvent e = w.apply(stay);
  EXPECT_TRUE(e.applied) << e.detail;
  EXPECT_EQ(loc(w, "t1"), "r1");
  world::Intervention add = iv(Kind::AddContainer, "t2");
  add.position = world::Vec3{0.40, 0.25, 0};
  EXPECT_TRUE(w.apply(add).applied);
  EXPECT_EQ(loc(w, "t2"), "r1");
  world::Intervention block = iv(Kind::Add, "x");
  block.position = world::Vec3{0.40, 0.25, 0.01};  // on a tray
  EXPECT_TRUE(w.apply(block).applied);
  EXPECT_TRUE(loc(w, "x") == "t1" || loc(w, "x") == "t2") << loc(w, "x");
  // A tray moved by the person is found where it went.
  ASSERT_TRUE(w.apply(iv(Kind::Relocate, "t2", "r4")).applied);
  world::Intervention onto = iv(Kind::Relocate, "o3");
  onto.position = world::Vec3{0.72, 0.40, 0.01};
  EXPECT_TRUE(w.apply(onto).applied);
  EXPECT_EQ(loc(w, "o3"), "t2");
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, OptionsOutOfRangeAreErrors) {
  auto with = [](auto change) {
    SymbolicWorldOptions o;
    change(o);
    return o;
  };
  EXPECT_THROW(SymbolicWorld(tiny(), with([](auto& o) { o.speed = 0; })), Error);
  EXPECT_THROW(SymbolicWorld(tiny(), with([](auto& o) { o.grasp = -1; })), Error);
  EXPECT_THROW(SymbolicWorld(tiny(), with([](auto& o) { o.failure_probability = 1.5; })), Error);
  EXPECT_THROW(SymbolicWorld(tiny(), with([](auto& o) { o.fails_in = Phase::Retreat; })), Error);
  EXPECT_THROW(SymbolicWorld(tiny(), with([](auto& o) { o.added_container_capacity = 0; })), Error);
  EXPECT_NO_THROW(SymbolicWorld(tiny(), with([](auto& o) { o.grasp = 0; })));
}

// ---------------------------------------------------------------- failures and halts

TEST(SymbolicWorld, DeterministicFailuresInEachPhase) {
  for (Phase p : {Phase::Approach, Phase::Grasp, Phase::Carry, Phase::Place}) {
    SCOPED_TRACE(to_string(p));
    SymbolicWorldOptions o;
    o.fails = [](const Move& m) { return m.thing == "o1"; };
    o.fails_in = p;
    SymbolicWorld w(tiny(), o);
    w.start(move("o1", "r1", "r2"));
    to_middle_of(w, p);
    step_phase(w);
    std::string why;
    if (p == Phase::Approach || p == Phase::Grasp) {
      EXPECT_EQ(w.phase(), Phase::Idle);
      EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
      EXPECT_NE(why.find("failed"), std::string::npos) << why;
      EXPECT_EQ(loc(w, "o1"), "r1");
      EXPECT_EQ(w.hand(), "");
    } else {
      EXPECT_EQ(w.phase(), Phase::Return);
      EXPECT_EQ(w.poll(nullptr), MoveStatus::Running);
      EXPECT_EQ(loc(w, "o1"), kInHand);
      EXPECT_FALSE(w.busy());
      run_until_idle(w);
      EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
      EXPECT_NE(why.find("put back in r1"), std::string::npos) << why;
      EXPECT_EQ(loc(w, "o1"), "r1");
      EXPECT_EQ(w.hand(), "r1");
    }
    // Other moves do not fail.
    w.start(move("o3", "r2", "r4"));
    run_until_idle(w);
    EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  }
}

TEST(SymbolicWorld, FailureWithAFullSourceGoesToTheClosestValidLocation) {
  SymbolicWorldOptions o;
  o.fails = [](const Move&) { return true; };
  o.fails_in = Phase::Place;
  SymbolicWorld w(tiny(), o);
  w.start(move("o1", "r1", "r2"));
  to_middle_of(w, Phase::Carry);
  ASSERT_TRUE(w.apply(iv(Kind::Add, "x", "r1")).applied);
  ASSERT_TRUE(w.apply(iv(Kind::Add, "y", "r1")).applied);  // r1: t1, x, y
  run_until_idle(w);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Failed);
  EXPECT_EQ(loc(w, "o1"), "t1");  // the tray stands in r1 (distance 0) and has room
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, SeededFailuresHitEveryPhaseAndAreDeterministic) {
  std::set<std::string> reasons;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SymbolicWorldOptions o;
    o.failure_probability = 1;
    o.seed = seed;
    SymbolicWorld a(tiny(), o), b(tiny(), o);
    for (SymbolicWorld* w : {&a, &b}) {
      w->start(move("o1", "r1", "r2"));
      run_until_idle(*w);
      EXPECT_EQ(loc(*w, "o1"), "r1");
    }
    std::string wa, wb;
    ASSERT_EQ(a.poll(&wa), MoveStatus::Failed);
    ASSERT_EQ(b.poll(&wb), MoveStatus::Failed);
    EXPECT_EQ(wa, wb);
    EXPECT_EQ(a.time(), b.time());
    reasons.insert(wa.substr(0, wa.find(' ')));
  }
  EXPECT_EQ(reasons, (std::set<std::string>{"approach", "grasp", "carry", "place"}));
  SymbolicWorldOptions never;
  never.failure_probability = 0;
  SymbolicWorld w(tiny(), never);
  w.start(move("o1", "r1", "r2"));
  run_until_idle(w);
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
}

TEST(SymbolicWorld, HaltInEachPhase) {
  struct Case {
    Phase phase;
    Phase after;     // the phase that makes the arm safe
    const char* o1;  // where o1 ends
  };
  for (const Case& c : {Case{Phase::Approach, Phase::Retreat, "r1"}, Case{Phase::Grasp, Phase::Retreat, "r1"},
                        Case{Phase::Carry, Phase::Return, "r1"}, Case{Phase::Place, Phase::Return, "r1"},
                        Case{Phase::Retreat, Phase::Retreat, "r2"}}) {
    SCOPED_TRACE(to_string(c.phase));
    SymbolicWorld w(tiny());
    w.start(move("o1", "r1", "r2"));
    to_middle_of(w, c.phase);
    w.halt();
    std::string why;
    EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
    EXPECT_EQ(why, "halted");
    EXPECT_TRUE(w.busy());
    EXPECT_EQ(w.phase(), c.after);
    EXPECT_GT(w.phase_end(), w.time());
    EXPECT_EQ(w.check_invariants(), "");
    w.halt();  // again: no change
    EXPECT_EQ(w.phase(), c.after);
    run_until_idle(w);
    EXPECT_FALSE(w.busy());
    EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
    EXPECT_EQ(why, "halted");
    EXPECT_EQ(loc(w, "o1"), c.o1);
    w.start(move("o3", "r2", "r4"));
    run_until_idle(w);
    EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  }
  SymbolicWorld idle(tiny());
  idle.halt();
  EXPECT_FALSE(idle.busy());
  EXPECT_EQ(idle.poll(nullptr), MoveStatus::Idle);
}

TEST(SymbolicWorld, HaltReturnTimeFollowsTheModel) {
  SymbolicWorld w(tiny());
  w.start(move("o1", "r1", "r2"));
  to_middle_of(w, Phase::Place);  // the hand is at r2
  w.halt();
  const world::Vec3 r1{0.4, 0.3, 0}, r2{0.4, -0.3, 0};
  EXPECT_NEAR(w.phase_end() - w.time(), 0.5 + dist(r2, r1) / 0.25 + 0.5, 1e-12);
}

TEST(SymbolicWorld, HaltWithTheSourceGoneReturnsToTheClosestValidLocation) {
  SymbolicWorld w(tiny());
  w.start(move("o2", "t1", "r2"));
  to_middle_of(w, Phase::Carry);
  ASSERT_TRUE(w.apply(iv(Kind::RemoveContainer, "t1")).applied);
  w.halt();
  EXPECT_TRUE(w.busy());
  run_until_idle(w);
  EXPECT_EQ(loc(w, "o2"), "r1");  // where the tray stood
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, TakingTheThingDuringAHaltReturnEndsIt) {
  SymbolicWorld w(tiny());
  w.start(move("o1", "r1", "r2"));
  to_middle_of(w, Phase::Carry);
  w.halt();
  ASSERT_TRUE(w.busy());
  ASSERT_TRUE(w.apply(iv(Kind::TakeFromGripper, "", "r4")).applied);
  EXPECT_FALSE(w.busy());
  std::string why;
  EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
  EXPECT_EQ(why, "halted");
  EXPECT_EQ(loc(w, "o1"), "r4");
}

// ---------------------------------------------------------------- scripted interventions

TEST(SymbolicWorld, ScriptedInterventionsApplyAtTheirExactTime) {
  world::Intervention late = iv(Kind::Relocate, "o3", "r4");
  late.time = 1.234;
  world::Intervention first = iv(Kind::Add, "x", "r2");
  first.time = 0;
  world::Intervention mid = iv(Kind::Remove, "o4");
  mid.time = 1.234;  // same time: kept in script order
  Acted a(tiny(), script({late, mid, first}));
  SymbolicWorld& w = a.w;
  EXPECT_EQ(loc(w, "x"), "r2");  // time 0: applied by the constructor
  EXPECT_EQ(a.person.next_time(), 1.234);
  EXPECT_EQ(a.pw.next_event_time(), std::numeric_limits<double>::infinity());  // idle: the loop ticks it
  w.start(move("o1", "r1", "r2"));
  const double approach_end = w.phase_end();
  ASSERT_GT(approach_end, 1.234);
  EXPECT_EQ(a.pw.next_event_time(), 1.234);
  a.pw.advance(1.0);
  EXPECT_EQ(loc(w, "o3"), "r2");
  EXPECT_EQ(a.pw.next_event_time(), 1.234);
  a.pw.advance(a.pw.next_event_time() - a.pw.time());
  EXPECT_EQ(loc(w, "o3"), "r4");
  EXPECT_EQ(loc(w, "o4"), "");
  const auto events = a.pw.take_events();
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].what.subject, "x");
  EXPECT_EQ(events[0].time, 0);
  EXPECT_EQ(events[1].what.subject, "o3");
  EXPECT_EQ(events[1].time, 1.234);
  EXPECT_EQ(events[2].what.subject, "o4");
  EXPECT_EQ(events[2].time, 1.234);
  EXPECT_EQ(w.phase_end(), approach_end);  // interventions do not change a running phase
  EXPECT_EQ(a.pw.next_event_time(), approach_end);
  while (w.phase() != Phase::Idle) a.pw.advance(a.pw.next_event_time() - a.pw.time());
  EXPECT_EQ(w.poll(nullptr), MoveStatus::Succeeded);
  EXPECT_TRUE(a.pw.take_events().empty());
}

TEST(SymbolicWorld, ScriptedInterventionInsideOneAdvanceInterruptsAtItsTime) {
  // The script takes o1 from the gripper during the carry; one long advance
  // must stop the move at that moment, not at the end of the carry.
  const double t_take = time_in(Phase::Carry, false);
  auto a = moving_o1_with(iv(Kind::TakeFromGripper, "", "r4"), t_take);
  a->pw.advance(100);
  EXPECT_EQ(a->w.poll(nullptr), MoveStatus::Failed);
  EXPECT_EQ(loc(a->w, "o1"), "r4");
  ASSERT_EQ(a->w.history().size(), 1u);
  EXPECT_EQ(a->w.history()[0].time, t_take);
  EXPECT_TRUE(a->w.history()[0].applied);
}

TEST(SymbolicWorld, TheScenarioScriptRunsWhenPassed) {
  const auto s = world::load_scenario("3-block-tray");
  Acted a(s, script(s.interventions));
  SymbolicWorld& w = a.w;
  w.start(move("o2", "r1", "r2"));
  while (w.phase() != Phase::Idle) a.pw.advance(a.pw.next_event_time() - a.pw.time());
  EXPECT_EQ(loc(w, "o2"), "r2");
  a.pw.advance(20 - w.time());
  EXPECT_EQ(loc(w, "o2"), "r1");
  ASSERT_EQ(w.history().size(), 1u);
  EXPECT_EQ(w.history()[0].time, 20);
}

TEST(SymbolicWorld, APhaseEndGoesBeforeAnInterventionAtTheSameTime) {
  const double grasp_end = time_in(Phase::Grasp, true);
  auto a = moving_o1_with(iv(Kind::TakeFromGripper, "", "r4"), grasp_end);
  a->pw.advance(grasp_end);
  ASSERT_EQ(a->w.history().size(), 1u);
  EXPECT_TRUE(a->w.history()[0].applied) << a->w.history()[0].detail;  // o1 was already in the gripper
  EXPECT_EQ(loc(a->w, "o1"), "r4");
}

TEST(SymbolicWorld, RandomInterventionsHappenWhenAnnounced) {
  world::PersonOptions po;
  po.rate = 1;
  po.seed = 3;
  Acted a(tiny(), po);
  SymbolicWorld& w = a.w;
  w.start(move("o1", "r1", "r2"));
  int mid_phase = 0;
  for (int i = 0; i < 200; ++i) {
    const double t = std::min(a.pw.next_event_time(), a.person.next_time());
    const bool phase_event = t == w.phase_end();
    const std::size_t before = w.history().size();
    a.pw.advance(t - w.time());
    ASSERT_NEAR(w.time(), t, 1e-9);
    if (!phase_event) {
      ASSERT_EQ(w.history().size(), before + 1);
      EXPECT_EQ(w.history().back().time, t);
      mid_phase += w.phase() != Phase::Idle;
    }
    ASSERT_EQ(w.check_invariants(), "");
    if (w.poll(nullptr) == MoveStatus::Running || w.busy()) continue;
    for (const auto& [name, thing] : w.truth().things) {  // move some object somewhere else
      if (thing.container) continue;
      w.start(move(name, "", thing.location == "r2" ? "r4" : "r2"));
      break;
    }
  }
  EXPECT_GT(mid_phase, 10);
}

// ---------------------------------------------------------------- footprint rules (world/fit.hpp)

// Trays of 30 x 16 cm (cell 0.0457 m²). a (cap 6, room 0.156 m²): tray t3
// holding o2, and o1; small (20 x 20 cm): no tray fits; pair (32 x 34 cm, room
// 0.133 m²): t1 and t2, no room for a third tray (room for blocks or a 24 x 16
// cm box); far (40 x 40 cm): brick b1 (20 x 20 cm: fits no tray). Distances from a: small 0.35 m, far
// 0.50 m, pair 0.60 m.
constexpr const char* kFitting = R"(
name: fitting
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: a, center: [0.40, 0.30, 0], size: [0.36, 0.36], capacity: 6}
  - {name: small, center: [0.75, 0.30, 0], size: [0.20, 0.20], capacity: 4}
  - {name: pair, center: [0.40, -0.30, 0], size: [0.32, 0.34], capacity: 4}
  - {name: far, center: [0.40, 0.80, 0], size: [0.40, 0.40], capacity: 8}
containers:
  - {name: t1, class: tray, position: [0.40, -0.215, 0], size: [0.30, 0.16, 0.03], capacity: 3}
  - {name: t2, class: tray, position: [0.40, -0.385, 0], size: [0.30, 0.16, 0.03], capacity: 3}
  - {name: t3, class: tray, position: [0.40, 0.30, 0], size: [0.30, 0.16, 0.03], capacity: 3}
objects:
  - {name: o1, class: block, position: [0.30, 0.44, 0], size: [0.04, 0.04, 0.04]}
  - {name: o2, class: block, position: [0.40, 0.30, 0.03], size: [0.04, 0.04, 0.04]}
  - {name: b1, class: brick, position: [0.40, 0.80, 0], size: [0.20, 0.20, 0.05]}
propositions: {done: "o1 in far"}
task: "F done"
)";

world::Scenario fitting() { return world::parse_scenario(kFitting, "fitting.yaml"); }

TEST(SymbolicWorld, TheFittingScenarioIsAsDescribed) {
  const SymbolicWorld w(fitting());
  ASSERT_EQ(w.check_invariants(), "");
  EXPECT_EQ(loc(w, "t1"), "pair");
  EXPECT_EQ(loc(w, "t2"), "pair");
  EXPECT_EQ(loc(w, "t3"), "a");
  EXPECT_EQ(loc(w, "o2"), "t3");
  EXPECT_EQ(loc(w, "b1"), "far");
  EXPECT_FALSE(w.fits("t3", "small"));
  EXPECT_TRUE(w.fits("t3", "pair"));
  EXPECT_FALSE(w.fits("b1", "t3"));
  EXPECT_LE(w.used("pair") + w.cell("o1", "pair"), w.room("pair"));
  EXPECT_GT(w.used("pair") + w.cell("t3", "pair"), w.room("pair"));
  EXPECT_EQ(w.fits("nothing", "a"), false);
  EXPECT_EQ(w.cell("nothing", "a"), -1);
  EXPECT_EQ(w.cell("o1", "nowhere"), -1);
  EXPECT_EQ(w.room("nowhere"), -1);
  EXPECT_EQ(w.used("nowhere"), -1);
}

TEST(SymbolicWorld, InterventionsFollowTheFootprintRules) {
  struct Case {
    const char* name;
    world::Intervention what;
    const char* why;    // "" = applied, else a substring of the refusal
    const char* where;  // where the subject is afterwards ("" = not in the world)
  };
  const std::vector<Case> cases{
      {"an added tray does not fit small", iv(Kind::AddContainer, "x", "small"), "x does not fit in small",
       ""},
      {"a tray relocated into small", iv(Kind::Relocate, "t3", "small"), "t3 does not fit in small", "a"},
      {"a third tray added to pair", iv(Kind::AddContainer, "x", "pair"), "pair has no room for x", ""},
      {"a third tray relocated to pair", iv(Kind::Relocate, "t3", "pair"), "pair has no room for t3", "a"},
      {"a block relocated to pair (room left)", iv(Kind::Relocate, "o1", "pair"), "", "pair"},
      {"a tray relocated to far", iv(Kind::Relocate, "t3", "far"), "", "far"},
      {"a tray added to far", iv(Kind::AddContainer, "x", "far"), "", "far"},
      {"an added container of a new class (24 x 16 cm) does not fit small",
       iv(Kind::AddContainer, "x", "small", "box"), "x does not fit in small", ""},
      {"an added container of a new class (24 x 16 cm) has no room in pair either (a third beside two)",
       iv(Kind::AddContainer, "x", "pair", "box"), "pair has no room for x", ""},
      {"an added brick (b1's size) does not fit a tray", iv(Kind::Add, "x", "t3", "brick"),
       "x does not fit in t3", ""},
      {"an added brick fits a region", iv(Kind::Add, "x", "a", "brick"), "", "a"},
      {"an added object of a new class (4 cm) fits a tray", iv(Kind::Add, "x", "t3", "pebble"), "", "t3"},
      {"the brick relocated onto a tray", iv(Kind::Relocate, "b1", "t3"), "b1 does not fit in t3", "far"},
      {"the brick relocated into small", iv(Kind::Relocate, "b1", "small"), "", "small"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    SymbolicWorld w(fitting());
    const world::Placement before = w.truth();
    const WorldEvent e = w.apply(c.what);
    EXPECT_EQ(e.applied, std::string(c.why).empty()) << e.detail;
    EXPECT_NE(e.detail.find(c.why), std::string::npos) << e.detail;
    EXPECT_EQ(loc(w, c.what.subject), c.where);
    if (!e.applied) {
      EXPECT_EQ(w.truth(), before);
    }
    EXPECT_EQ(w.check_invariants(), "");
  }
}

TEST(SymbolicWorld, MovesFollowTheFootprintRules) {
  struct Case {
    const char* name;
    Move m;
    const char* why;    // "" = Succeeded, else a substring of the failure
    const char* where;  // where the thing ends
  };
  const std::vector<Case> cases{
      {"a tray into small", move("t3", "a", "small"), "t3 does not fit in small", "a"},
      {"a third tray into pair", move("t3", "a", "pair"), "pair has no room for t3", "a"},
      {"the brick onto a tray", move("b1", "far", "t3"), "b1 does not fit in t3", "far"},
      {"a tray into far", move("t3", "a", "far"), "", "far"},
      {"a tray from pair into a", move("t1", "pair", "a"), "", "a"},
      {"a block into pair", move("o1", "a", "pair"), "", "pair"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    SymbolicWorld w(fitting());
    w.start(c.m);
    run_until_idle(w);
    std::string why;
    EXPECT_EQ(w.poll(&why), std::string(c.why).empty() ? MoveStatus::Succeeded : MoveStatus::Failed) << why;
    EXPECT_NE(why.find(c.why), std::string::npos) << why;
    EXPECT_EQ(loc(w, c.m.thing), c.where);
    EXPECT_EQ(loc(w, "o2"), "t3");  // the tray's contents travel with it
    EXPECT_EQ(w.hand(), c.where);
    EXPECT_EQ(w.check_invariants(), "");
  }
}

TEST(SymbolicWorld, PutBacksGoToTheClosestLocationWhereTheThingFitsAndHasRoom) {
  SymbolicWorld w(fitting());
  w.start(move("t3", "a", "pair"));  // no room in pair: the place fails
  to_middle_of(w, Phase::Carry);
  // While t3 is carried, a fills up: o1 and two trays leave no room for t3 (capacity 6 would allow it).
  for (const char* x : {"x1", "x2"}) ASSERT_TRUE(w.apply(iv(Kind::AddContainer, x, "a")).applied);
  EXPECT_NE(w.refusal("t3", "a").find("a has no room for t3"), std::string::npos) << w.refusal("t3", "a");
  EXPECT_NE(w.refusal("t3", "small").find("does not fit"), std::string::npos);
  // The gripper cannot hand it over into small either: the move goes on.
  const WorldEvent take = w.apply(iv(Kind::TakeFromGripper, "", "small"));
  EXPECT_FALSE(take.applied);
  EXPECT_NE(take.detail.find("t3 does not fit in small"), std::string::npos) << take.detail;
  EXPECT_NE(take.detail.find("t3 stays in the gripper"), std::string::npos) << take.detail;
  EXPECT_EQ(loc(w, "t3"), kInHand);
  run_until_idle(w);
  std::string why;
  EXPECT_EQ(w.poll(&why), MoveStatus::Failed);
  EXPECT_NE(why.find("pair has no room for t3"), std::string::npos) << why;
  // small (0.35 m) is closer than far (0.50 m), but t3 does not fit there.
  EXPECT_NE(why.find("put back in far"), std::string::npos) << why;
  EXPECT_EQ(loc(w, "t3"), "far");
  EXPECT_EQ(loc(w, "o2"), "t3");
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, SpilledContentsGoWhereTheyHaveRoom) {
  // The tray t (30 x 16 cm) holds three 4 cm blocks in a row (room, not its
  // capacity 12); snug (32 x 18 cm, capacity 5) holds the tray and three blocks
  // (room, not capacity). Removing the tray spills its three blocks: two into
  // snug (then at its capacity 5), one into side.
  world::Scenario s = world::parse_scenario(R"(
name: snug
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: snug, center: [0.40, 0.30, 0], size: [0.32, 0.18], capacity: 5}
  - {name: side, center: [0.40, -0.30, 0], size: [0.40, 0.40], capacity: 20}
containers:
  - {name: t, class: tray, position: [0.40, 0.30, 0], size: [0.30, 0.16, 0.03], capacity: 12}
objects:
  - {name: o1, class: block, position: [0.40, -0.30, 0], size: [0.04, 0.04, 0.04]}
propositions: {done: "o1 in snug"}
task: "F done"
)",
                                            "snug.yaml");
  SymbolicWorld w(s);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(w.apply(iv(Kind::Add, "in" + std::to_string(i), "t")).applied);
  EXPECT_NE(w.apply(iv(Kind::Add, "in3", "t")).detail.find("t has no room for in3"), std::string::npos);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(w.apply(iv(Kind::Add, "by" + std::to_string(i), "snug")).applied);
  EXPECT_NE(w.apply(iv(Kind::Add, "by3", "snug")).detail.find("snug has no room for by3"), std::string::npos);
  const WorldEvent e = w.apply(iv(Kind::RemoveContainer, "t"));
  ASSERT_TRUE(e.applied);
  std::map<std::string, int> spilled;
  for (int i = 0; i < 3; ++i) ++spilled[loc(w, "in" + std::to_string(i))];
  EXPECT_EQ(spilled, (std::map<std::string, int>{{"side", 1}, {"snug", 2}})) << e.detail;
  EXPECT_NE(e.detail.find("(snug has no room)"), std::string::npos) << e.detail;
  EXPECT_EQ(w.check_invariants(), "");
}

TEST(SymbolicWorld, AnInitialPlacementThatBreaksTheFootprintRulesIsAccepted) {
  world::Scenario s = fitting();
  s.containers[2].position = {0.75, 0.30, 0};  // t3 in small, where it does not fit
  world::Container t4 = s.containers[0];       // a third tray in pair, which has room for two
  t4.name = "t4";
  s.containers.push_back(t4);
  SymbolicWorld w(s);
  ASSERT_EQ(loc(w, "t3"), "small");
  ASSERT_EQ(loc(w, "t4"), "pair");
  EXPECT_EQ(w.check_invariants(), "");
  EXPECT_NO_THROW(task::System{s});  // the planner accepts it too
  // Nothing more goes into pair while it is over its room; small still takes a block.
  EXPECT_NE(w.apply(iv(Kind::Relocate, "o1", "pair")).detail.find("pair has no room for o1"),
            std::string::npos);
  EXPECT_TRUE(w.apply(iv(Kind::Relocate, "o1", "small")).applied);
  // Once moved away, the things do not go back.
  ASSERT_TRUE(w.apply(iv(Kind::Relocate, "t3", "far")).applied);
  EXPECT_NE(w.apply(iv(Kind::Relocate, "t3", "small")).detail.find("t3 does not fit in small"),
            std::string::npos);
  ASSERT_TRUE(w.apply(iv(Kind::Relocate, "t4", "a")).applied);
  EXPECT_NE(w.apply(iv(Kind::Relocate, "t4", "pair")).detail.find("pair has no room for t4"),
            std::string::npos);
  EXPECT_TRUE(w.apply(iv(Kind::Relocate, "o1", "pair")).applied);  // room for a block beside two trays
  EXPECT_EQ(w.check_invariants(), "");
}

// The scenario of the world as it is now, built by this test's own reading of
// the size rule (a scenario thing keeps its size; an added one takes the size
// of the first scenario thing of its class, else the default), and the
// placement without the things at "none".
std::pair<world::Scenario, world::Placement> planner_view(const world::Scenario& base,
                                                          const SymbolicWorld& w) {
  world::Scenario s = base;
  s.objects.clear();
  s.containers.clear();
  world::Placement p;
  for (const auto& [name, thing] : w.truth().things) {
    if (thing.location == world::kNoLocation) continue;
    p.things[name] = thing;
    if (thing.container) {
      world::Container c;
      c.name = name;
      c.cls = thing.cls;
      c.capacity = w.capacity(name);
      const world::Container* same = base.find_container(name);
      for (const auto& k : base.containers)
        if (!same && k.cls == thing.cls) same = &k;
      if (same) c.size = same->size;
      s.containers.push_back(c);
    } else {
      world::Object o;
      o.name = name;
      o.cls = thing.cls;
      const world::Object* same = base.find_object(name);
      for (const auto& k : base.objects)
        if (!same && k.cls == thing.cls) same = &k;
      if (same) o.size = same->size;
      s.objects.push_back(o);
    }
  }
  return {s, p};
}

// Random scenes: regions of several sizes in a line, trays and objects of
// several classes and sizes at random places (on trays too); capacities large,
// so that the footprint rules bind.
world::Scenario random_fit_scene(std::uint64_t seed) {
  std::uint64_t r = seed * 0x9E3779B97F4A7C15ull + 5;
  auto next = [&r](std::uint64_t n) {
    r = r * 6364136223846793005ull + 1442695040888963407ull;
    return (r >> 33) % n;
  };
  const std::vector<double> sides{0.16, 0.20, 0.24, 0.28, 0.32, 0.40};
  const std::vector<world::Vec3> tray_sizes{{0.30, 0.16, 0.03}, {0.24, 0.16, 0.03}, {0.18, 0.18, 0.03}};
  const std::vector<std::pair<const char*, world::Vec3>> object_kinds{
      {"block", {0.04, 0.04, 0.04}}, {"brick", {0.12, 0.06, 0.05}}, {"slab", {0.20, 0.14, 0.02}}};
  world::Scenario s;
  s.name = "random-fit-" + std::to_string(seed);
  const int M = 2 + static_cast<int>(next(3));
  for (int i = 0; i < M; ++i) {
    world::Region g;
    g.name = "r" + std::to_string(i + 1);
    g.center = {0.5, -0.5 * (M - 1) / 2.0 + 0.5 * i, 0};
    g.size = {sides[next(sides.size())], sides[next(sides.size())]};
    g.capacity = 12;
    s.regions.push_back(g);
  }
  const int C = static_cast<int>(next(4));
  for (int i = 0; i < C; ++i) {
    world::Container c;
    c.name = "t" + std::to_string(i + 1);
    c.cls = i % 2 ? "crate" : "tray";
    c.size = tray_sizes[next(tray_sizes.size())];
    c.position = s.regions[next(s.regions.size())].center;
    c.capacity = 6;
    s.containers.push_back(c);
  }
  const int N = 1 + static_cast<int>(next(6));
  for (int i = 0; i < N; ++i) {
    world::Object o;
    o.name = "o" + std::to_string(i + 1);
    const auto& kind = object_kinds[next(object_kinds.size())];
    o.cls = kind.first;
    o.size = kind.second;
    o.position = s.regions[next(s.regions.size())].center;
    if (!s.containers.empty() && next(3) == 0)
      o.position[0] += 0.3;  // beside the trays (in the region or nowhere)
    s.objects.push_back(o);
  }
  return s;
}

TEST(SymbolicWorld, AgreesWithTheTransitionSystemOnFitAndRoom) {
  int fit_refusals = 0, room_refusals = 0, accepted = 0, compared = 0;
  std::vector<std::pair<std::string, world::Scenario>> scenes{
      {"fitting", fitting()}, {"tiny", tiny()}, {"3-block-tray", world::load_scenario("3-block-tray")}};
  for (std::uint64_t seed = 1; seed <= 40; ++seed)
    scenes.emplace_back("random " + std::to_string(seed), random_fit_scene(seed));
  for (const auto& [label, scene] : scenes) {
    SCOPED_TRACE(label);
    SymbolicWorld w(scene);
    std::uint64_t r = 1469598103934665603ull;  // FNV-1a of the label: the same walk on every platform
    for (unsigned char ch : label) r = (r ^ ch) * 1099511628211ull;
    auto next = [&r](std::uint64_t n) {
      r = r * 6364136223846793005ull + 1442695040888963407ull;
      return (r >> 33) % n;
    };
    const std::vector<const char*> classes{"block", "brick", "slab", "pebble"},
        container_classes{"tray", "crate", "box"};
    for (int step = 0; step < 40; ++step) {
      ASSERT_EQ(w.check_invariants(), "");
      // Compare every (thing, location) with a transition system built from the same world.
      const auto [s, p] = planner_view(scene, w);
      const task::System ts(s, p, w.hand());
      const task::State st = ts.initial();
      int counts[task::kMaxLocations + 1];
      std::int64_t used[task::kMaxLocations + 1];
      ts.occupancy(st, counts, used);
      for (unsigned l = 0; l < ts.num_locations(); ++l) {
        const std::string& ln = ts.location_name(l);
        ASSERT_EQ(w.room(ln), ts.room(l)) << ln;
        ASSERT_EQ(w.used(ln), used[l]) << ln;
      }
      for (unsigned t = 0; t < ts.num_things(); ++t) {
        const std::string& tn = ts.thing_name(t);
        for (unsigned l = 0; l < ts.num_locations(); ++l) {
          const std::string& ln = ts.location_name(l);
          ASSERT_EQ(w.cell(tn, ln), ts.cell(t, l)) << tn << " in " << ln;
          ASSERT_EQ(w.fits(tn, ln), ts.fits(t, l)) << tn << " in " << ln;
          if (ts.location(st, t) == l) continue;
          const std::string why = w.refusal(tn, ln);
          ASSERT_EQ(why.empty(), ts.enabled(st, task::Action::move(static_cast<std::uint16_t>(t),
                                                                   static_cast<std::uint16_t>(l))))
              << "move(" << tn << ", " << ln << "): " << why << " in " << ts.to_string(st);
          ++compared;
          fit_refusals += why.find("does not fit") != std::string::npos;
          room_refusals += why.find("has no room for") != std::string::npos;
        }
      }
      // A random intervention (targets not filtered: many are refused).
      std::vector<std::string> things, locations;
      for (const auto& [n, t] : w.truth().things) things.push_back(n);
      for (const auto& g : scene.regions) locations.push_back(g.name);
      for (const auto& [n, t] : w.truth().things)
        if (t.container) locations.push_back(n);
      const std::string fresh = "n" + std::to_string(step);
      const std::string to = locations[next(locations.size())];
      WorldEvent e;
      switch (next(6)) {
        case 0:
        case 1:
        case 2:
          if (things.empty()) continue;
          e = w.apply(iv(Kind::Relocate, things[next(things.size())], to));
          break;
        case 3:
          e = w.apply(iv(Kind::Add, fresh, to, classes[next(classes.size())]));
          break;
        case 4:
          e = w.apply(iv(Kind::AddContainer, fresh, to, container_classes[next(container_classes.size())]));
          break;
        default:
          if (things.empty()) continue;
          const std::string victim = things[next(things.size())];
          e = w.apply(
              iv(w.truth().things.at(victim).container ? Kind::RemoveContainer : Kind::Remove, victim));
          break;
      }
      accepted += e.applied;
    }
  }
  RecordProperty("compared", compared);
  RecordProperty("fit_refusals", fit_refusals);
  RecordProperty("room_refusals", room_refusals);
  RecordProperty("accepted", accepted);
  EXPECT_GT(compared, 10000);
  EXPECT_GT(fit_refusals, 100);
  EXPECT_GT(room_refusals, 100);
  EXPECT_GT(accepted, 300);
}

// ---------------------------------------------------------------- random interventions

// A crude loop: start random moves, sometimes halt, jump to the next event.
struct RandomRun {
  std::vector<WorldEvent> events;
  std::vector<std::string> outcomes;
  double end_time = 0;
};

RandomRun random_run(const world::Scenario& s, std::uint64_t seed, int steps, std::string* broken,
                     std::map<Kind, int>* applied_kinds = nullptr) {
  SymbolicWorldOptions o;
  o.seed = seed;
  o.failure_probability = 0.2;
  world::PersonOptions po;
  po.seed = seed;
  po.rate = 0.5;
  Acted a(s, po, o);
  SymbolicWorld& w = a.w;
  std::uint64_t r = seed * 7919 + 1;
  auto next = [&r](std::uint64_t n) {
    r = r * 6364136223846793005ull + 1442695040888963407ull;
    return (r >> 33) % n;
  };
  RandomRun run;
  for (int i = 0; i < steps && broken->empty(); ++i) {
    if (w.poll(nullptr) != MoveStatus::Running && !w.busy()) {
      const auto p = w.observe();
      std::vector<std::string> things, locations;
      for (const auto& [n, t] : p.things) things.push_back(n);
      for (const auto& rg : s.regions) locations.push_back(rg.name);
      for (const auto& [n, t] : p.things)
        if (t.container) locations.push_back(n);
      if (!things.empty()) {
        const std::string thing = things[next(things.size())];
        const std::string to = locations[next(locations.size())];
        w.start(move(thing, next(8) ? *p.location_of(thing) : "r1", to));
      }
    } else if (next(20) == 0) {
      w.halt();
    }
    const double t = std::min(a.pw.next_event_time(), a.person.next_time());
    a.pw.advance(std::isfinite(t) ? t - w.time() : 1.0);
    *broken = w.check_invariants();
    std::string why;
    const MoveStatus st = w.poll(&why);
    run.outcomes.push_back(std::string(to_string(st)) + " " + why + " " + to_string(w.phase()));
    for (auto& e : w.take_events()) {
      if (e.applied && applied_kinds) ++(*applied_kinds)[e.what.kind];
      run.events.push_back(std::move(e));
    }
  }
  run.end_time = w.time();
  return run;
}

TEST(SymbolicWorld, RandomInterventionsKeepTheInvariants) {
  std::map<Kind, int> applied;
  int refused = 0, steps = 0;
  for (const char* name : {"tiny", "fitting", "3-block-tray", "3-block"}) {
    const std::string n = name;
    const auto s = n == "tiny" ? tiny() : n == "fitting" ? fitting() : world::load_scenario(name);
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
      std::string broken;
      const RandomRun run = random_run(s, seed, 100, &broken, &applied);
      ASSERT_EQ(broken, "") << name << " seed " << seed;
      for (const auto& e : run.events) {
        EXPECT_FALSE(e.detail.empty());
        if (!e.applied) ++refused;
      }
      steps += static_cast<int>(run.outcomes.size());
    }
  }
  EXPECT_GE(steps, 15000);
  for (Kind k : {Kind::Relocate, Kind::Add, Kind::Remove, Kind::AddContainer, Kind::RemoveContainer,
                 Kind::TakeFromGripper})
    EXPECT_GT(applied[k], 0) << static_cast<int>(k);
  EXPECT_GT(refused, 0);
}

TEST(SymbolicWorld, DeterministicPerSeed) {
  const auto s = tiny();
  std::string broken;
  const RandomRun a = random_run(s, 5, 300, &broken), b = random_run(s, 5, 300, &broken),
                  c = random_run(s, 6, 300, &broken);
  ASSERT_EQ(broken, "");
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].time, b.events[i].time);
    EXPECT_EQ(a.events[i].detail, b.events[i].detail);
  }
  EXPECT_EQ(a.outcomes, b.outcomes);
  EXPECT_EQ(a.end_time, b.end_time);
  EXPECT_NE(a.end_time, c.end_time);
}

TEST(SymbolicWorld, RandomInterventionsStayInTheirWindowAndGetFreshNames) {
  world::PersonOptions o;
  o.rate = 5;
  o.start = 10;
  o.end = 20;
  o.kinds = {Kind::Add};
  Acted a(world::load_scenario("3-block"), o);
  SymbolicWorld& w = a.w;
  EXPECT_GE(a.person.next_time(), 10);
  a.pw.advance(100);
  ASSERT_FALSE(w.history().empty());
  std::set<std::string> names;
  for (const auto& e : w.history()) {
    EXPECT_GE(e.time, 10);
    EXPECT_LT(e.time, 20);
    EXPECT_EQ(e.what.subject[0], 'x');
    EXPECT_TRUE(names.insert(e.what.subject).second);
    EXPECT_EQ(e.what.cls, "block");
  }
  EXPECT_EQ(a.person.next_time(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(w.check_invariants(), "");
}

}  // namespace
}  // namespace rtamp::exec
