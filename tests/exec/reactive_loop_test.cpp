// The reactive loop (Algorithm 1) on the symbolic world, case by case: the
// issue's failures on the old loop (tasks with history, a tray removed
// mid-carry, a block taken from the gripper), task progress and what the loop
// does when the history makes the task unsatisfiable, recurring tasks with
// cycles, stop(), intervention counts, and a table of every intervention kind
// at moments spread over the first moves (every phase of a move).
#include "rtamp/exec/reactive_loop.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

// Two regions r1 (start) and r2 far apart, r3 between, a tray class, blocks of two classes.
world::Scenario scene(const std::string& task, int blocks = 2, bool tray = false) {
  std::string y = R"(name: loop-test
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.30, 0.30], capacity: 5}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.30, 0.30], capacity: 5}
  - {name: r3, center: [0.60, 0.0, 0], size: [0.30, 0.20], capacity: 5}
objects:
)";
  for (int i = 1; i <= blocks; ++i)
    y += "  - {name: o" + std::to_string(i) + ", class: " + (i == 1 ? "red" : "block") + ", position: [" +
         std::to_string(0.30 + 0.06 * i) + ", 0.40, 0], size: [0.04, 0.04, 0.04]}\n";
  if (tray) y += "containers:\n  - {name: t1, class: tray, position: [0.40, 0.25, 0], size: [0.24, 0.12, 0.03], capacity: 4}\n";
  y += R"(propositions:
  all_in_r1: "all object in r1"
  all_in_r2: "all object in r2"
  o1_in_r2: "o1 in r2"
  o1_in_r3: "o1 in r3"
  red_in_r3: "all red in r3"
)";
  y += "task: \"" + task + "\"\n";
  return world::parse_scenario(y, "<test>");
}

LoopOptions inline_options() {
  LoopOptions o;
  o.planning = PlanningMode::Inline;
  o.max_time = 300;
  o.world_name = "symbolic";
  return o;
}

struct Moves : EpisodeObserver {
  std::vector<std::string> finished, started, plans;
  std::vector<double> finished_at;
  void on_action(double t, const char* what, const std::string& action, const std::string&) override {
    if (std::string(what) == "finished") {
      finished.push_back(action);
      finished_at.push_back(t);
    }
    if (std::string(what) == "start") started.push_back(action);
  }
  void on_plan(double, const PlanEvent& e) override {
    std::string s;
    for (const auto& t : e.tuples) s += t.action + " ";
    plans.push_back(s);
  }
  std::size_t count(const std::string& a) const { return static_cast<std::size_t>(std::count(finished.begin(), finished.end(), a)); }
};

world::Intervention intervention(world::Intervention::Kind kind, double t, std::string subject, std::string to = {},
                                 std::string cls = {}) {
  world::Intervention iv;
  iv.kind = kind;
  iv.time = t;
  iv.subject = std::move(subject);
  iv.location = std::move(to);
  iv.cls = std::move(cls);
  return iv;
}

// The issue's first example: o1 must visit r2, then everything stays in r1.
// The old loop forgot the visit and shuttled o1 until the time limit.
TEST(ReactiveLoop, TaskWithHistoryFinishes) {
  const world::Scenario s = scene("F (o1_in_r2 & F G all_in_r1)");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Moves moves;
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.end, EndReason::TaskDone);
  EXPECT_EQ(moves.count("move(o1, r2)"), 1u);
  EXPECT_EQ(moves.count("move(o1, r1)"), 1u);
  EXPECT_EQ(moves.finished.size(), 2u);
  EXPECT_EQ(w.truth().things.at("o1").location, "r1");
}

// After the red block has been in r3 a person puts it back into r1: the loop
// must take it to r2, not to r3 again (the visit already happened).
TEST(ReactiveLoop, FinishedWorkIsNotRedoneAfterAnIntervention) {
  world::Scenario s = scene("F (red_in_r3 & F G all_in_r2)", 3);
  SymbolicWorld probe(s);
  ReactiveLoop first(probe, s, inline_options());
  Moves pm;
  first.add_observer(pm);
  ASSERT_TRUE(first.run().success);
  const auto visit = std::find(pm.finished.begin(), pm.finished.end(), "move(o1, r3)");
  ASSERT_NE(visit, pm.finished.end());
  const double visited = pm.finished_at[static_cast<std::size_t>(visit - pm.finished.begin())];
  // A person puts o1 back into r1 a second after it has been in r3.
  SymbolicWorldOptions wo;
  wo.script = {intervention(world::Intervention::Kind::Relocate, visited + 1.0, "o1", "r1")};
  SymbolicWorld w(s, wo);
  ReactiveLoop loop(w, s, inline_options());
  Moves moves;
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(moves.count("move(o1, r3)"), 1u) << "red was taken to r3 again";
}

// The history makes the task unsatisfiable: it ends at once, with the reason.
TEST(ReactiveLoop, HistoryThatViolatesTheTaskEndsAtOnce) {
  const world::Scenario s = scene("F G all_in_r2 & G !o1_in_r3");
  SymbolicWorldOptions wo;
  wo.script = {intervention(world::Intervention::Kind::Relocate, 1.0, "o1", "r3")};
  SymbolicWorld w(s, wo);
  ReactiveLoop loop(w, s, inline_options());
  const EpisodeMetrics& m = loop.run();
  EXPECT_FALSE(m.success);
  EXPECT_EQ(m.end, EndReason::Unsatisfiable) << m.reason;
  EXPECT_LT(m.world_time, 2.0);
  EXPECT_FALSE(m.completion_time.has_value());
}

TEST(ReactiveLoop, PatrolEndsAfterTheRequestedCycles) {
  const world::Scenario s = scene("G F o1_in_r2 & G F o1_in_r3", 1);
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  o.cycles = 3;
  ReactiveLoop loop(w, s, o);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.end, EndReason::Cycles);
  EXPECT_EQ(m.cycles, 3);
  EXPECT_EQ(loop.cycle_marks().size(), 3u);
}

TEST(ReactiveLoop, PatrolWithoutCyclesRunsToTheTimeLimitAndSaysWhy) {
  const world::Scenario s = scene("G F o1_in_r2 & G F o1_in_r3", 1);
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  o.max_time = 60;
  ReactiveLoop loop(w, s, o);
  const EpisodeMetrics& m = loop.run();
  EXPECT_FALSE(m.success);
  EXPECT_EQ(m.end, EndReason::TimeLimit);
  EXPECT_NE(m.reason.find("--cycles"), std::string::npos) << m.reason;
  EXPECT_GE(m.cycles, 2);
}

// The tray the arm is carrying a block to is taken away: the block is put
// somewhere valid and the loop replans; no error.
TEST(ReactiveLoop, TrayRemovedMidCarrySurvives) {
  const world::Scenario s = scene("F G all_in_r2", 3, true);
  SymbolicWorld probe(s);
  ReactiveLoop first(probe, s, inline_options());
  Moves pm;
  first.add_observer(pm);
  ASSERT_TRUE(first.run().success);
  ASSERT_NE(pm.finished.front().find("t1"), std::string::npos) << "the plan does not use the tray";
  for (double t = 0.2; t < 6; t += 0.3) {
    SymbolicWorldOptions wo;
    wo.script = {intervention(world::Intervention::Kind::RemoveContainer, t, "t1")};
    SymbolicWorld w(s, wo);
    ReactiveLoop loop(w, s, inline_options());
    const EpisodeMetrics& m = loop.run();
    EXPECT_TRUE(m.success) << "t = " << t << ": " << m.reason;
    EXPECT_TRUE(w.check_invariants().empty());
  }
}

// A block taken out of the gripper and put into r1: the next plan moves it.
TEST(ReactiveLoop, BlockTakenFromTheGripperIsPlannedFromWhereItWasPut) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  for (double t = 0.6; t < 4; t += 0.2) {
    SymbolicWorldOptions wo;
    wo.script = {intervention(world::Intervention::Kind::TakeFromGripper, t, "", "r3")};
    SymbolicWorld w(s, wo);
    ReactiveLoop loop(w, s, inline_options());
    const EpisodeMetrics& m = loop.run();
    EXPECT_TRUE(m.success) << "t = " << t << ": " << m.reason;
    EXPECT_EQ(w.truth().things.at("o1").location, "r2");
    EXPECT_EQ(w.truth().things.at("o2").location, "r2");
  }
}

TEST(ReactiveLoop, StopEndsTheEpisodeWithCompleteMetrics) {
  const world::Scenario s = scene("F G all_in_r2", 3);
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  struct End : EpisodeObserver {
    int ends = 0;
    void on_end(double, const EpisodeMetrics&, const world::Placement&) override { ++ends; }
  } end;
  loop.add_observer(end);
  for (int i = 0; i < 5; ++i) loop.step();
  loop.stop();
  EXPECT_FALSE(loop.step());
  EXPECT_EQ(loop.metrics().end, EndReason::Interrupted);
  EXPECT_FALSE(loop.metrics().success);
  EXPECT_EQ(end.ends, 1);
  EXPECT_FALSE(loop.step());
  EXPECT_EQ(end.ends, 1);
}

// A thing put outside every location, then taken away, is forgotten: the
// episode does not wait for it (it used to wait until the time limit).
TEST(ReactiveLoop, AThingOutsideThatIsRemovedIsForgotten) {
  const world::Scenario s = scene("F G all_in_r2", 3);
  SymbolicWorldOptions wo;
  world::Intervention out = intervention(world::Intervention::Kind::Relocate, 1.0, "o3");
  out.position = world::Vec3{1.5, 1.5, 0};  // on the table, outside every region
  wo.script = {out, intervention(world::Intervention::Kind::Remove, 2.0, "o3")};
  SymbolicWorld w(s, wo);
  ReactiveLoop loop(w, s, inline_options());
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions_applied, 2);
  EXPECT_LT(m.world_time, 100);
}

TEST(ReactiveLoop, RefusedInterventionsAreCountedAsRefused) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  SymbolicWorldOptions wo;
  wo.script = {intervention(world::Intervention::Kind::Relocate, 1.0, "nothing", "r1"),
               intervention(world::Intervention::Kind::Relocate, 2.0, "o2", "r3")};
  SymbolicWorld w(s, wo);
  ReactiveLoop loop(w, s, inline_options());
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions, 2);
  EXPECT_EQ(m.interventions_applied, 1);
  EXPECT_EQ(m.interventions_refused, 1);
}

// A move that fails with nobody disturbing it is not planned again while the
// world is unchanged: a block that cannot be placed in r3 (the nearer goal) goes to r2.
TEST(ReactiveLoop, AMoveThatFailedIsNotRepeatedWhileTheWorldIsUnchanged) {
  const world::Scenario s = scene("F G all_in_r2 | F G red_in_r3", 1);
  SymbolicWorldOptions wo;
  wo.fails = [](const Move& m) { return m.to == "r3"; };
  SymbolicWorld w(s, wo);
  ReactiveLoop loop(w, s, inline_options());
  Moves moves;
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(std::count(moves.started.begin(), moves.started.end(), "move(o1, r3)"), 1);
  EXPECT_EQ(w.truth().things.at("o1").location, "r2");
  EXPECT_EQ(m.actions_failed, 1);
}

// Every kind of intervention at moments spread over the first moves (so every
// phase of a move): never an error, and success or a reason that fits.
TEST(ReactiveLoop, EveryInterventionAtEveryMoment) {
  using K = world::Intervention::Kind;
  const world::Scenario s = scene("F (red_in_r3 & F G all_in_r2)", 3, true);
  const std::vector<world::Intervention> kinds = {
      intervention(K::Relocate, 0, "o1", "r1"),       intervention(K::Relocate, 0, "o2", "r3"),
      intervention(K::Relocate, 0, "t1", "r3"),       intervention(K::Add, 0, "x9", "r1", "block"),
      intervention(K::Remove, 0, "o2"),               intervention(K::Remove, 0, "o1"),
      intervention(K::AddContainer, 0, "t9", "r1", "tray"), intervention(K::RemoveContainer, 0, "t1"),
      intervention(K::TakeFromGripper, 0, "", "r1"),  intervention(K::TakeFromGripper, 0, "", "")};
  int episodes = 0, succeeded = 0;
  for (const auto& base : kinds)
    for (double t = 0.1; t < 12; t += 0.35) {
      world::Intervention iv = base;
      iv.time = t;
      SymbolicWorldOptions wo;
      wo.script = {iv};
      SymbolicWorld w(s, wo);
      ReactiveLoop loop(w, s, inline_options());
      const EpisodeMetrics& m = loop.run();
      ++episodes;
      SCOPED_TRACE("kind " + std::to_string(static_cast<int>(iv.kind)) + " " + iv.subject + " at t = " +
                   std::to_string(t));
      EXPECT_NE(m.end, EndReason::Error) << m.reason;
      EXPECT_NE(m.end, EndReason::TimeLimit) << m.reason;
      EXPECT_TRUE(w.check_invariants().empty()) << w.check_invariants();
      // None of these can make the task impossible (removing the red block
      // makes "all red in r3" vacuously true), so every episode must succeed.
      if (m.success) ++succeeded;
      else ADD_FAILURE() << to_string(m.end) << ": " << m.reason;
    }
  EXPECT_EQ(succeeded, episodes);
}

}  // namespace
}  // namespace rtamp::exec
