// PerceptionErrorWorld (exec/perception_errors.hpp) over the symbolic world: a
// person's change shows exactly `delay` late (or `late_delay`), changes made
// together show together and consistently (a tray and what it held), the
// gripper's doings show at once, a move towards a change not shown yet
// reveals it, false removals last their duration and come at about their
// rate, everything is reproducible, and bad numbers are refused.
#include "rtamp/exec/perception_errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

using Kind = world::Intervention::Kind;

// r1: o1 and tray t1 holding o2; r2: o3.
constexpr const char* kScene = R"(
name: scene
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.30, 0], size: [0.36, 0.36], capacity: 4}
  - {name: r2, center: [0.40, -0.30, 0], size: [0.36, 0.36], capacity: 4}
containers:
  - {name: t1, class: tray, position: [0.40, 0.25, 0], size: [0.24, 0.16, 0.03], capacity: 2}
objects:
  - {name: o1, class: block, position: [0.40, 0.42, 0]}
  - {name: o2, class: block, position: [0.40, 0.25, 0.01]}
  - {name: o3, class: block, position: [0.40, -0.30, 0]}
propositions: {done: "o1 in r2"}
task: "F done"
)";

world::Scenario scene() { return world::parse_scenario(kScene, "scene.yaml"); }

world::Intervention iv(Kind k, std::string subject, std::string location = "") {
  world::Intervention i;
  i.kind = k;
  i.subject = std::move(subject);
  i.location = std::move(location);
  return i;
}

std::string where(World& w, const std::string& name) {
  const world::Placement p = w.observe();
  const std::string* at = p.location_of(name);
  return at ? *at : "gone";
}

TEST(PerceptionErrors, APersonsChangeShowsExactlyTheDelayLate) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  PerceptionErrors e;
  e.delay = 0.4;
  PerceptionErrorWorld w(truth, s, e);
  truth.advance(1.0);
  ASSERT_TRUE(truth.apply(iv(Kind::Relocate, "o3", "r1")).applied);
  EXPECT_EQ(where(w, "o3"), "r2");  // noticed now, shown at 1.4
  EXPECT_TRUE(w.differs());
  truth.advance(0.39);
  EXPECT_EQ(where(w, "o3"), "r2");
  truth.advance(0.01);
  EXPECT_EQ(where(w, "o3"), "r1");
  EXPECT_FALSE(w.differs());
}

// A change is being confirmed in the last `delay` before it shows (the camera sees it,
// the belief makes sure); before that, a late change is hidden from the camera.
TEST(PerceptionErrors, AChangeIsConfirmedOnlyInTheLastDelayBeforeItShows) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  PerceptionErrors e;
  e.delay = 0.4;
  e.late_probability = 1;
  e.late_delay = 2;
  PerceptionErrorWorld w(truth, s, e);
  EXPECT_FALSE(w.confirming());
  ASSERT_TRUE(truth.apply(iv(Kind::Relocate, "o3", "r1")).applied);
  EXPECT_EQ(where(w, "o3"), "r2");  // noticed now, shown at 2
  EXPECT_FALSE(w.confirming());
  truth.advance(1.5);
  EXPECT_FALSE(w.confirming());
  truth.advance(0.1);
  EXPECT_TRUE(w.confirming());
  EXPECT_EQ(where(w, "o3"), "r2");
  truth.advance(0.4);
  EXPECT_EQ(where(w, "o3"), "r1");
  EXPECT_FALSE(w.confirming());
}

TEST(PerceptionErrors, ChangesMadeTogetherShowTogetherAndConsistently) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  PerceptionErrors e;
  e.delay = 0.5;
  PerceptionErrorWorld w(truth, s, e);
  ASSERT_TRUE(truth.apply(iv(Kind::RemoveContainer, "t1")).applied);  // o2 falls into r1
  EXPECT_EQ(where(w, "t1"), "r1");
  EXPECT_EQ(where(w, "o2"), "t1");
  truth.advance(0.5);
  EXPECT_EQ(where(w, "t1"), "gone");
  EXPECT_EQ(where(w, "o2"), "r1");
  // A thing added into a tray added a moment later: shown no earlier than its tray.
  world::Intervention tray = iv(Kind::AddContainer, "t2", "r2");
  tray.cls = "tray";
  ASSERT_TRUE(truth.apply(tray).applied);
  (void)w.observe();  // t2 noticed at 0.5, due at 1.0
  truth.advance(0.2);
  world::Intervention block = iv(Kind::Add, "b9", "t2");
  block.cls = "block";
  ASSERT_TRUE(truth.apply(block).applied);
  for (int i = 0; i < 12; ++i) {
    const world::Placement p = w.observe();
    if (const std::string* in = p.location_of("b9")) {
      EXPECT_TRUE(p.things.count(*in)) << "b9 shown in t2 before t2";
    }
    truth.advance(0.1);
  }
  EXPECT_EQ(where(w, "b9"), "t2");
}

TEST(PerceptionErrors, TheGrippersDoingsShowAtOnce) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  PerceptionErrors e;
  e.delay = 5;
  PerceptionErrorWorld w(truth, s, e);
  w.start({"move(o1, r2)", "o1", "r1", "r2"});
  bool held = false;
  while (truth.poll(nullptr) == MoveStatus::Running) {
    truth.advance(std::max(1e-3, truth.next_event_time() - truth.time()));
    const std::string at = where(w, "o1");
    held = held || at == kInHand;
    EXPECT_EQ(at, *truth.observe().location_of("o1")) << "at t = " << truth.time();
  }
  EXPECT_TRUE(held);
  EXPECT_EQ(where(w, "o1"), "r2");
}

TEST(PerceptionErrors, AMoveTowardsAChangeNotShownYetRevealsIt) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  PerceptionErrors e;
  e.delay = 5;
  PerceptionErrorWorld w(truth, s, e);
  ASSERT_TRUE(truth.apply(iv(Kind::Relocate, "o3", "r1")).applied);
  ASSERT_TRUE(truth.apply(iv(Kind::RemoveContainer, "t1")).applied);
  EXPECT_EQ(where(w, "o3"), "r2");
  EXPECT_EQ(where(w, "t1"), "r1");
  w.start({"move(o3, t1)", "o3", "r2", "t1"});  // both changes are where the arm goes
  std::string why;
  EXPECT_EQ(w.poll(&why), MoveStatus::Failed) << why;
  EXPECT_EQ(where(w, "o3"), "r1");
  EXPECT_EQ(where(w, "t1"), "gone");
  EXPECT_EQ(where(w, "o2"), "r1");  // what t1 held came with it
}

TEST(PerceptionErrors, LateChangesComeAtTheirProbability) {
  const world::Scenario s = scene();
  int late = 0;
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    SymbolicWorld truth(s);
    PerceptionErrors e;
    e.delay = 0.1;
    e.late_probability = 0.25;
    e.late_delay = 2;
    e.seed = static_cast<std::uint64_t>(k);
    PerceptionErrorWorld w(truth, s, e);
    ASSERT_TRUE(truth.apply(iv(Kind::Relocate, "o3", "r1")).applied);
    (void)w.observe();
    truth.advance(0.1);
    late += where(w, "o3") == "r2" ? 1 : 0;
    truth.advance(1.9);
    EXPECT_EQ(where(w, "o3"), "r1");
  }
  EXPECT_NEAR(static_cast<double>(late) / n, 0.25, 0.07);  // 3.3 standard deviations
}

TEST(PerceptionErrors, FalseRemovalsLastTheirDurationAtAboutTheirRate) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  PerceptionErrors e;
  e.false_removal_rate = 0.05;  // 4 things: 0.2 a second
  e.false_removal_duration = 0.3;
  e.seed = 7;
  PerceptionErrorWorld w(truth, s, e);
  int removals = 0;
  std::map<std::string, double> gone_since;
  const double step = 0.01;
  for (int i = 0; i < 100'000; ++i) {  // 1,000 s
    const world::Placement p = w.observe();
    for (const auto& name : {"o1", "o2", "o3"}) {
      const bool seen = p.things.count(name) > 0;
      if (!seen && !gone_since.count(name)) {
        gone_since[name] = truth.time();
        ++removals;
      } else if (seen && gone_since.count(name)) {
        EXPECT_NEAR(truth.time() - gone_since[name], 0.3, step + 1e-9) << name;
        gone_since.erase(name);
      }
    }
    EXPECT_TRUE(p.things.count("t1")) << "containers are never falsely removed";
    truth.advance(step);
  }
  // Poisson at 0.05 x 4 shown things = 0.2/s over 1,000 s: mean 200, each draw hiding one of
  // the blocks (never the tray): within 4 standard deviations.
  EXPECT_NEAR(removals, 200, 4 * std::sqrt(200.0));
}

TEST(PerceptionErrors, TheSameSeedGivesTheSameErrors) {
  const world::Scenario s = scene();
  auto run = [&](std::uint64_t seed) {
    SymbolicWorld truth(s);
    PerceptionErrors e;
    e.false_removal_rate = 0.1;
    e.false_removal_duration = 0.2;
    e.seed = seed;
    PerceptionErrorWorld w(truth, s, e);
    std::string trace;
    for (int i = 0; i < 2000; ++i) {
      trace += std::to_string(w.observe().things.size());
      truth.advance(0.01);
    }
    return trace;
  };
  EXPECT_EQ(run(3), run(3));
  EXPECT_NE(run(3), run(4));
}

TEST(PerceptionErrors, BadNumbersAreRefused) {
  const world::Scenario s = scene();
  SymbolicWorld truth(s);
  for (double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    PerceptionErrors e;
    e.delay = bad;
    EXPECT_THROW(PerceptionErrorWorld(truth, s, e), Error);
    e = {};
    e.false_removal_rate = bad;
    EXPECT_THROW(PerceptionErrorWorld(truth, s, e), Error);
  }
  PerceptionErrors e;
  e.late_probability = 1.5;
  try {
    PerceptionErrorWorld w(truth, s, e);
    ADD_FAILURE() << "accepted late_probability 1.5";
  } catch (const Error& x) {
    EXPECT_NE(std::string(x.what()).find("late_probability"), std::string::npos) << x.what();
  }
}

}  // namespace
}  // namespace rtamp::exec
