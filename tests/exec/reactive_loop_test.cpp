// The reactive loop (Algorithm 1) on the symbolic world, case by case: the
// issue's failures on the old loop (tasks with history, a tray removed
// mid-carry, a block taken from the gripper), task progress and what the loop
// does when the history makes the task unsatisfiable, recurring tasks with
// cycles, stop(), intervention counts, and a table of every intervention kind
// at moments spread over the first moves (every phase of a move).
#include "rtamp/exec/reactive_loop.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "rtamp/exec/forwarding_world.hpp"
#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/util/error.hpp"
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

// An episode on the symbolic world with a person's script (world/person.hpp
// through exec::PersonWorld), the loop on top.
struct Scripted {
  SymbolicWorld w;
  world::Person person;
  PersonWorld acted;
  ReactiveLoop loop;
  Scripted(const world::Scenario& s, std::vector<world::Intervention> script, LoopOptions o = inline_options())
      : w(s), person(s, person_with(std::move(script))), acted(w, person), loop(acted, s, std::move(o)) {}
  static world::PersonOptions person_with(std::vector<world::Intervention> script) {
    world::PersonOptions po;
    po.script = std::move(script);
    return po;
  }
};

struct Moves : EpisodeObserver {
  std::vector<std::string> finished, started, plans;
  std::vector<double> finished_at, started_at;
  void on_action(double t, const char* what, const std::string& action, const std::string&) override {
    if (std::string(what) == "finished") {
      finished.push_back(action);
      finished_at.push_back(t);
    }
    if (std::string(what) == "start") {
      started.push_back(action);
      started_at.push_back(t);
    }
  }
  void on_plan(double, const PlanEvent& e) override {
    std::string s;
    for (const auto& t : e.tuples) s += t.action + " ";
    plans.push_back(s);
  }
  std::size_t started_after(const std::string& a, double t) const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < started.size(); ++i) n += started[i] == a && started_at[i] > t;
    return n;
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
  Scripted e(s, {intervention(world::Intervention::Kind::Relocate, visited + 1.0, "o1", "r1")});
  ReactiveLoop& loop = e.loop;
  Moves moves;
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(moves.count("move(o1, r3)"), 1u) << "red was taken to r3 again";
}

// The history makes the task unsatisfiable: it ends at once, with the reason.
TEST(ReactiveLoop, HistoryThatViolatesTheTaskEndsAtOnce) {
  const world::Scenario s = scene("F G all_in_r2 & G !o1_in_r3");
  Scripted e(s, {intervention(world::Intervention::Kind::Relocate, 1.0, "o1", "r3")});
  ReactiveLoop& loop = e.loop;
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

// Every third move fails, so no tree of the patrol (prefix and a 4-move cycle)
// ever runs to its end: the rounds the run closes anyway are counted, and the
// episode ends after them with no move running.
TEST(ReactiveLoop, APatrolCountsTheRoundsItsRunClosesAcrossReplans) {
  const world::Scenario s = scene("G F all_in_r1 & G F all_in_r2", 2);
  SymbolicWorldOptions wo;
  auto started = std::make_shared<int>(0);
  wo.fails = [started](const Move&) { return ++*started % 3 == 0; };
  SymbolicWorld w(s, wo);
  LoopOptions o = inline_options();
  o.cycles = 3;
  o.max_failures_per_move = 1000;
  o.max_time = 3000;
  ReactiveLoop loop(w, s, o);
  Moves moves;
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_EQ(m.end, EndReason::Cycles) << m.reason;
  EXPECT_TRUE(m.success);
  EXPECT_EQ(m.cycles, 3);
  EXPECT_GT(m.actions_failed, 2);
  EXPECT_GT(moves.plans.size(), 3u);  // replanned after the failures
  EXPECT_FALSE(w.busy());
  // Each counted round returns to a state the run had since the previous count.
  const auto& run = loop.observed_run();
  std::size_t from = 0;
  for (std::size_t mark : loop.cycle_marks()) {
    bool back = false;
    for (std::size_t j = from; j < mark && !back; ++j) back = run[j] == run[mark];
    EXPECT_TRUE(back) << "the round ending at step " << mark << " returns to no earlier state";
    from = mark;
  }
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
    Scripted e(s, {intervention(world::Intervention::Kind::RemoveContainer, t, "t1")});
    SymbolicWorld& w = e.w;
    ReactiveLoop& loop = e.loop;
    const EpisodeMetrics& m = loop.run();
    EXPECT_TRUE(m.success) << "t = " << t << ": " << m.reason;
    EXPECT_TRUE(w.check_invariants().empty());
  }
}

// A block taken out of the gripper and put into r1: the next plan moves it.
TEST(ReactiveLoop, BlockTakenFromTheGripperIsPlannedFromWhereItWasPut) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  for (double t = 0.6; t < 4; t += 0.2) {
    Scripted e(s, {intervention(world::Intervention::Kind::TakeFromGripper, t, "", "r3")});
    SymbolicWorld& w = e.w;
    ReactiveLoop& loop = e.loop;
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

// At the end a finished tree keeps its statuses (the root SUCCESS: what a page
// shows last), and a tree still running when the time is up is halted: the move
// stops, every node is INVALID, the world is not left busy with it.
TEST(ReactiveLoop, TheEndHaltsOnlyARunningTree) {
  const world::Scenario s = scene("F G all_in_r2", 3);
  {
    SymbolicWorld w(s);
    ReactiveLoop loop(w, s, inline_options());
    ASSERT_TRUE(loop.run().success);
    EXPECT_EQ(loop.tree().tree().status(), bt::Status::Success);
  }
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  o.max_time = 1.0;  // within the first move
  ReactiveLoop loop(w, s, o);
  Moves moves;
  struct Halted : EpisodeObserver {
    int halted = 0;
    void on_action(double, const char* what, const std::string&, const std::string&) override {
      halted += std::string(what) == "halted";
    }
  } halted;
  loop.add_observer(moves);
  loop.add_observer(halted);
  EXPECT_FALSE(loop.run().success);
  EXPECT_EQ(loop.metrics().end, EndReason::TimeLimit);
  ASSERT_EQ(moves.started.size(), 1u);
  EXPECT_EQ(halted.halted, 1);
  EXPECT_EQ(loop.tree().tree().status(), bt::Status::Invalid);
}

// A thing put outside every location, then taken away, is forgotten: the
// episode does not wait for it (it used to wait until the time limit).
TEST(ReactiveLoop, AThingOutsideThatIsRemovedIsForgotten) {
  const world::Scenario s = scene("F G all_in_r2", 3);
  world::Intervention out = intervention(world::Intervention::Kind::Relocate, 1.0, "o3");
  out.position = world::Vec3{0.85, 0.55, 0};  // on the table, outside every region
  Scripted e(s, {out, intervention(world::Intervention::Kind::Remove, 2.0, "o3")});
  ReactiveLoop& loop = e.loop;
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions_applied, 2);
  EXPECT_LT(m.world_time, 100);
}

TEST(ReactiveLoop, RefusedInterventionsAreCountedAsRefused) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  Scripted e(s, {intervention(world::Intervention::Kind::Relocate, 1.0, "nothing", "r1"),
               intervention(world::Intervention::Kind::Relocate, 2.0, "o2", "r3")});
  ReactiveLoop& loop = e.loop;
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

// ---- liveness: the robot never idles with work to do ----

// A world that forwards to another and lets a test spoil its answers.
using Forward = ForwardingWorld;  // tests override what they spoil

struct Starts : EpisodeObserver {
  std::vector<double> at;
  void on_action(double t, const char* what, const std::string&, const std::string&) override {
    if (std::string(what) == "start") at.push_back(t);
  }
};

// A discrete-event world with a person scheduled late: the first move starts
// at t = 0 (it used to wait for the person), and an unrelated late
// intervention changes no completion time.
TEST(ReactiveLoop, TheFirstMoveStartsAtOnceAndALatePersonChangesNothing) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  auto episode = [&](std::vector<world::Intervention> script, std::vector<double>* starts) {
    Scripted e(s, std::move(script));
    ReactiveLoop& loop = e.loop;
    Starts st;
    loop.add_observer(st);
    EpisodeMetrics m = loop.run();
    if (starts) *starts = st.at;
    return m;
  };
  std::vector<double> starts;
  const EpisodeMetrics alone = episode({}, &starts);
  ASSERT_TRUE(alone.success) << alone.reason;
  ASSERT_FALSE(starts.empty());
  EXPECT_EQ(starts.front(), 0.0);
  // A person adds a tray to r3 long after the task is done, or during it.
  for (double t : {100.0, 0.7, 3.1}) {
    std::vector<double> with_starts;
    const EpisodeMetrics m =
        episode({intervention(world::Intervention::Kind::AddContainer, t, "t9", "r3", "tray")}, &with_starts);
    ASSERT_TRUE(m.success) << m.reason;
    EXPECT_EQ(with_starts.front(), 0.0) << "person at t = " << t;
    EXPECT_EQ(*m.completion_time, *alone.completion_time) << "person at t = " << t;
  }
}

// A task already true at the start is done at t = 0, before a person acts.
TEST(ReactiveLoop, ATaskTrueAtTheStartIsDoneAtOnce) {
  const world::Scenario s = scene("F G all_in_r1", 2);
  Scripted e(s, {intervention(world::Intervention::Kind::Relocate, 10, "o1", "r2")});
  ReactiveLoop& loop = e.loop;
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(*m.completion_time, 0.0);
  EXPECT_EQ(m.actions_succeeded, 0);
  EXPECT_EQ(m.interventions, 0);
}

// In worker mode the plan is charged its planning time; the first move starts
// as soon as the plan is in, not at the person's time.
TEST(ReactiveLoop, WorkerPlanningStartsAsSoonAsThePlanIsIn) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  LoopOptions o = inline_options();
  o.planning = PlanningMode::Worker;
  Scripted e(s, {intervention(world::Intervention::Kind::AddContainer, 20, "t9", "r3", "tray")}, o);
  ReactiveLoop& loop = e.loop;
  Starts st;
  loop.add_observer(st);
  const EpisodeMetrics& m = loop.run();
  ASSERT_TRUE(m.success) << m.reason;
  ASSERT_FALSE(st.at.empty());
  EXPECT_LE(st.at.front(), m.first_plan_seconds + 1e-9);
}

// ---- failures ----

// A cost model that gives euclid's costs until `bad` is set, then -1.
struct GoesBad : plan::MotionCostModel {
  plan::EuclidCost euclid;
  std::atomic<bool> bad{false};
  std::string name() const override { return "goes-bad"; }
  double cost(const plan::MotionQuery& q) const override { return bad ? -1.0 : euclid.cost(q); }
  double lower_bound(const plan::MotionQuery& q, bool anywhere) const override {
    return euclid.lower_bound(q, anywhere);
  }
  unsigned depends() const override { return euclid.depends(); }
  bool expensive() const override { return false; }
};

// The model goes bad once the first plan is in.
struct SpoilAfterFirstPlan : EpisodeObserver {
  GoesBad* model = nullptr;
  void on_plan(double, const PlanEvent&) override { model->bad = true; }
};

// A cost model's bad value ends the episode with an error naming the model
// and the edge, for the first plan and for a replan, planned inline or on the
// worker thread.
TEST(ReactiveLoop, ACostModelsBadValueEndsTheEpisodeWithAnErrorNamingIt) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  for (const PlanningMode mode : {PlanningMode::Inline, PlanningMode::Worker})
    for (const bool first : {true, false}) {
      SCOPED_TRACE(std::string(mode == PlanningMode::Worker ? "worker" : "inline") + (first ? " first" : " replan"));
      auto model = std::make_shared<GoesBad>();
      model->bad = first;
      LoopOptions o = inline_options();
      o.planning = mode;
      o.planner.model = model;
      Scripted e(s, {intervention(world::Intervention::Kind::AddContainer, 1, "t9", "r3", "tray")}, o);
      SpoilAfterFirstPlan spoil;
      spoil.model = model.get();
      e.loop.add_observer(spoil);
      const EpisodeMetrics& m = e.loop.run();
      EXPECT_EQ(m.end, EndReason::Error) << m.reason;
      EXPECT_NE(m.reason.find("motion-cost model 'goes-bad' returned -1 for move("), std::string::npos) << m.reason;
    }
}

// A patrol lap whose move always fails: the same move from the same state is
// tried max_failures_per_move times, whatever succeeds in between, then the
// episode gives up naming the move and the rule.
TEST(ReactiveLoop, APatrolWithAMoveThatAlwaysFailsGivesUpNamingIt) {
  const world::Scenario s = scene("G F o1_in_r2 & G F o1_in_r3", 1);
  SymbolicWorldOptions wo;
  wo.fails = [](const Move& m) { return m.to == "r3"; };
  SymbolicWorld w(s, wo);
  LoopOptions o = inline_options();
  o.max_time = 3000;
  ReactiveLoop loop(w, s, o);
  Moves moves;
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_EQ(m.end, EndReason::GaveUp) << m.reason;
  EXPECT_NE(m.reason.find("move(o1, r3) failed 5 times from the same state"), std::string::npos) << m.reason;
  EXPECT_NE(m.reason.find("max_failures_per_move = 5"), std::string::npos) << m.reason;
  EXPECT_EQ(m.actions_failed, 5);
}

// Every tree form (state or action conditions, online or offline changes)
// counts and reports the same completed moves.
TEST(ReactiveLoop, EveryTreeFormCountsTheSameMoves) {
  const world::Scenario s = scene("F (red_in_r3 & F G all_in_r2)", 3, true);
  std::vector<int> counts;
  for (ConditionMode c : {ConditionMode::Action, ConditionMode::State})
    for (Reconfiguration r : {Reconfiguration::Online, Reconfiguration::Offline}) {
      SymbolicWorld w(s);
      LoopOptions o = inline_options();
      o.conditions = c;
      o.reconfiguration = r;
      ReactiveLoop loop(w, s, o);
      Moves moves;
      loop.add_observer(moves);
      const EpisodeMetrics& m = loop.run();
      SCOPED_TRACE(std::string(to_string(c)) + (r == Reconfiguration::Online ? " online" : " offline"));
      ASSERT_TRUE(m.success) << m.reason;
      EXPECT_EQ(static_cast<std::size_t>(m.actions_succeeded), moves.finished.size());
      EXPECT_EQ(m.actions_failed, 0);
      counts.push_back(m.actions_succeeded);
    }
  EXPECT_GT(counts.front(), 0);
  for (int c : counts) EXPECT_EQ(c, counts.front());
}

// A block dropped on the bare table: no move of it starts, the loop waits the
// grace, then ends `lost`; the end's placement has the block outside.
TEST(ReactiveLoop, ABlockDroppedOffTheRegionsIsLostAfterTheGrace) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  world::Intervention drop = intervention(world::Intervention::Kind::Relocate, 0.2, "o2");
  drop.position = world::Vec3{0.85, 0.0, 0};  // on the table, in no region
  Scripted e(s, {drop});
  ReactiveLoop& loop = e.loop;
  struct End : EpisodeObserver {
    world::Placement placement;
    void on_end(double, const EpisodeMetrics&, const world::Placement& p) override { placement = p; }
  } end;
  Moves moves;
  loop.add_observer(end);
  loop.add_observer(moves);
  const EpisodeMetrics& m = loop.run();
  EXPECT_EQ(m.end, EndReason::Lost) << m.reason;
  EXPECT_NEAR(m.world_time, 0.2 + 3.0, 0.05);
  EXPECT_EQ(moves.started_after("move(o2, r2)", 0.2), 0u);
  EXPECT_EQ(end.placement.things.at("o2").location, "none");
}

// ---- a world's answers are checked ----

TEST(ReactiveLoop, AWorldWhoseTimeIsNotANumberOrGoesBackIsAnError) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  struct Spoilt : Forward {
    using Forward::Forward;
    double bad = 0;  // NaN, or how far time jumps back once past 1 s
    double time() const override { return inner_.time() > 1.0 ? (std::isnan(bad) ? bad : inner_.time() - bad) : inner_.time(); }
  };
  for (double bad : {std::nan(""), 100.0}) {
    SymbolicWorld inner(s);
    Spoilt w(inner);
    w.bad = bad;
    ReactiveLoop loop(w, s, inline_options());
    const EpisodeMetrics& m = loop.run();
    EXPECT_EQ(m.end, EndReason::Error) << m.reason;
    EXPECT_NE(m.reason.find(std::isnan(bad) ? "time() returned nan" : "time() went back"), std::string::npos)
        << m.reason;
  }
}

TEST(ReactiveLoop, AWorldThatNamesAnUnknownLocationIsAnError) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  struct Spoilt : Forward {
    using Forward::Forward;
    world::Placement observe() override {
      world::Placement p = inner_.observe();
      if (inner_.time() > 1.0) p.things.at("o1").location = "r9";
      return p;
    }
  };
  SymbolicWorld inner(s);
  Spoilt w(inner);
  ReactiveLoop loop(w, s, inline_options());
  const EpisodeMetrics& m = loop.run();
  EXPECT_EQ(m.end, EndReason::Error) << m.reason;
  EXPECT_NE(m.reason.find("observe() puts 'o1' in 'r9'"), std::string::npos) << m.reason;
}

// A perception that briefly shows `thing` elsewhere ("" hides it) from `from` to `to`,
// unless the gripper has it.
struct Glitch : Forward {
  std::string thing, shown;
  double from, to;
  Glitch(World& w, std::string t, std::string at, double a, double b)
      : Forward(w), thing(std::move(t)), shown(std::move(at)), from(a), to(b) {}
  double next_event_time() const override {
    double t = inner_.next_event_time();
    for (double edge : {from, to})
      if (edge > inner_.time()) t = std::min(t, edge);
    return t;
  }
  world::Placement observe() override {
    world::Placement p = inner_.observe();
    const auto it = p.things.find(thing);
    if (inner_.time() >= from && inner_.time() < to && it != p.things.end() && it->second.location != kInHand) {
      if (shown.empty()) {
        p.things.erase(it);
      } else {
        it->second.location = shown;
      }
    }
    return p;
  }
};

// A percept is judged only once it has settled: a glitch shorter than `settle`
// that makes the task look done (o1 unseen while o2 is carried to r2), or
// impossible (o1 seen in r3), ends nothing; without settling it ends the
// episode wrongly.
TEST(ReactiveLoop, TheTaskIsJudgedOnlyOnASettledPercept) {
  for (const bool impossible : {false, true}) {
    SCOPED_TRACE(impossible ? "looks impossible" : "looks done");
    const world::Scenario s = scene(impossible ? "F G all_in_r2 & G !o1_in_r3" : "F G all_in_r2", 2);
    const double glitch = impossible ? 0.3 : 9;  // o2 is carried first, until t = 7.9
    for (const double settle : {0.0, glitch + 0.2}) {
      SymbolicWorld inner(s);
      Glitch w(inner, "o1", impossible ? "r3" : "", 0.1, 0.1 + glitch);
      LoopOptions o = inline_options();
      o.settle = settle;
      ReactiveLoop loop(w, s, o);
      const EpisodeMetrics& m = loop.run();
      if (settle == 0) {
        EXPECT_EQ(m.end, impossible ? EndReason::Unsatisfiable : EndReason::TaskDone) << m.reason;
        EXPECT_LT(m.world_time, 0.1 + glitch);
        EXPECT_EQ(*inner.truth().location_of("o1"), "r1");
        continue;
      }
      EXPECT_EQ(m.end, EndReason::TaskDone) << m.reason;
      EXPECT_EQ(*inner.truth().location_of("o1"), "r2");
      EXPECT_EQ(*inner.truth().location_of("o2"), "r2");
      for (const auto& p : loop.observed_run()) {
        const std::string* at = p.location_of("o1");
        EXPECT_TRUE(!at || *at != "r3") << "the glitch stayed in the run";
      }
    }
  }
}

// A percept is not settled while the world is confirming a change it has seen (a
// camera's belief making sure a new thing is one): o2, unseen at first, shows at
// t = 12 after being confirmed since t = 0.1. A world that does not say so has the
// task judged done on o1 alone, with o2 still in r1.
TEST(ReactiveLoop, APerceptIsNotSettledWhileTheWorldIsConfirmingAChange) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  struct Confirming : Glitch {
    bool says;
    Confirming(World& w, bool say) : Glitch(w, "o2", "", 0, 12), says(say) {}
    bool confirming() const override { return says && inner_.time() >= 0.1 && inner_.time() < 12; }
  };
  for (const bool says : {false, true}) {
    SCOPED_TRACE(says ? "says it is confirming" : "does not say");
    SymbolicWorld inner(s);
    Confirming w(inner, says);
    LoopOptions o = inline_options();
    o.settle = 0.5;
    ReactiveLoop loop(w, s, o);
    const EpisodeMetrics& m = loop.run();
    EXPECT_EQ(m.end, EndReason::TaskDone) << m.reason;
    EXPECT_EQ(*inner.truth().location_of("o1"), "r2");
    EXPECT_EQ(*inner.truth().location_of("o2"), says ? "r2" : "r1");
    if (says) EXPECT_GT(m.world_time, 12);
    else EXPECT_LT(m.world_time, 12);
  }
}

// An end caused by a person's intervention names it.
TEST(ReactiveLoop, AnEndCausedByAnInterventionNamesIt) {
  const world::Scenario s = scene("F G all_in_r2 & G !o1_in_r3");
  Scripted e(s, {intervention(world::Intervention::Kind::Relocate, 1.0, "o1", "r3")});
  ReactiveLoop& loop = e.loop;
  const EpisodeMetrics& m = loop.run();
  EXPECT_EQ(m.end, EndReason::Unsatisfiable) << m.reason;
  EXPECT_NE(m.reason.find("after the intervention at t = 1"), std::string::npos) << m.reason;
  EXPECT_NE(m.reason.find("move o1 r3"), std::string::npos) << m.reason;
}

// ---- a user's own world with the intervention capability ----

// A world of the user's, written from the World contract alone: moves take
// 2 s, a person may relocate things (the capability). The one Person drives
// it as it drives the built-in worlds.
class OwnWorld final : public World, public Intervenable {
 public:
  explicit OwnWorld(const world::Scenario& s) : place_(world::initial_placement(s)) {}
  double time() const override { return t_; }
  void advance(double dt) override {
    const double target = t_ + dt;
    if (moving_ && end_ <= target) {
      t_ = end_;
      moving_ = false;
      place_.things.at(move_.thing).location = move_.to;
      hand_ = move_.to;
      status_ = MoveStatus::Succeeded;
    }
    t_ = std::max(t_, target);
  }
  double next_event_time() const override { return moving_ ? end_ : std::numeric_limits<double>::infinity(); }
  world::Placement observe() override {
    world::Placement p = place_;
    if (moving_) p.things.at(move_.thing).location = kInHand;
    return p;
  }
  void start(const Move& m) override {
    move_ = m;
    moving_ = true;
    end_ = t_ + 2.0;
    status_ = MoveStatus::Running;
  }
  MoveStatus poll(std::string*) override { return status_; }
  void halt() override {
    moving_ = false;
    status_ = MoveStatus::Failed;
  }
  bool busy() override { return false; }
  std::string hand() const override { return hand_; }
  std::vector<WorldEvent> take_events() override { return std::exchange(events_, {}); }
  Intervenable* intervenable() override { return this; }
  world::Placement true_placement() override { return observe(); }
  WorldEvent apply(const world::Intervention& iv) override {
    WorldEvent e{t_, iv, iv.kind == world::Intervention::Kind::Relocate && place_.things.count(iv.subject) > 0, ""};
    if (e.applied) {
      if (moving_ && move_.thing == iv.subject) halt();
      place_.things.at(iv.subject).location = iv.location;
    }
    events_.push_back(e);
    return e;
  }

 private:
  world::Placement place_;
  double t_ = 0, end_ = 0;
  bool moving_ = false;
  Move move_;
  MoveStatus status_ = MoveStatus::Idle;
  std::string hand_;
  std::vector<WorldEvent> events_;
};

TEST(ReactiveLoop, APersonDrivesAUsersOwnWorldThroughItsCapability) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  OwnWorld own(s);
  world::PersonOptions po;
  po.script = {intervention(world::Intervention::Kind::Relocate, 3.0, "o1", "r1"),
               intervention(world::Intervention::Kind::Relocate, 3.0, "o2", "r3")};
  world::Person person(s, po);
  PersonWorld acted(own, person);
  ReactiveLoop loop(acted, s, inline_options());
  Starts st;
  loop.add_observer(st);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions_applied, 2);
  EXPECT_EQ(st.at.front(), 0.0);
  EXPECT_EQ(own.true_placement().things.at("o2").location, "r2");
}

TEST(ReactiveLoop, APersonNeedsAWorldThatTakesInterventions) {
  const world::Scenario s = scene("F G all_in_r2", 2);
  SymbolicWorld inner(s);
  struct Plain : Forward {  // forwards everything but the capability
    using Forward::Forward;
    Intervenable* intervenable() override { return nullptr; }
  } plain(inner);
  world::Person person(s, {});
  try {
    PersonWorld acted(plain, person, "my robot");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("my robot cannot take a person's interventions"), std::string::npos)
        << e.what();
  }
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
      Scripted e(s, {iv});
      SymbolicWorld& w = e.w;
      ReactiveLoop& loop = e.loop;
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
