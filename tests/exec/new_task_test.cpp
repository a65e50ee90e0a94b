// A new task while the robot works (ReactiveLoop::set_task and
// LoopOptions::task_changes; docs/exec.md "A new task"), on the symbolic
// world: a running move the new task can use goes on and the next one starts
// within a tick; one that would defeat it is halted and reported; a task the
// current state satisfies ends the episode at once, one it cannot satisfy
// ends it unsatisfiable naming the change; the run before the change does not
// count; cycles count for the task in force; bad tasks are refused at once
// (and reported), before the episode (scheduled ones) or during it (set_task).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <tuple>
#include <thread>

#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

world::Scenario scene(const std::string& task, int blocks = 2) {
  std::string y = R"(name: new-task-test
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.30, 0.30], capacity: 5}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.30, 0.30], capacity: 5}
  - {name: r3, center: [0.60, 0.0, 0], size: [0.30, 0.20], capacity: 5}
objects:
)";
  for (int i = 1; i <= blocks; ++i)
    y += "  - {name: o" + std::to_string(i) + ", class: block, position: [" + std::to_string(0.30 + 0.06 * i) +
         ", 0.40, 0], size: [0.04, 0.04, 0.04]}\n";
  y += R"(propositions:
  all_in_r1: "all object in r1"
  all_in_r2: "all object in r2"
  all_in_r3: "all object in r3"
  o1_in_r1: "o1 in r1"
  o1_in_r2: "o1 in r2"
  o1_in_r3: "o1 in r3"
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

world::TaskChange change(const std::string& task, double time = 0) {
  world::TaskChange c;
  c.time = time;
  c.task = task;
  c.by = "test";
  return c;
}

struct Watch : EpisodeObserver {
  struct Act {
    std::string what, action;
    double t;
  };
  std::vector<Act> acts;
  std::vector<std::pair<std::string, std::string>> redirects;
  std::vector<std::string> applied, refused;
  void on_action(double t, const char* what, const std::string& action, const std::string&) override {
    acts.push_back({what, action, t});
  }
  void on_task(double, const TaskEvent& e) override {
    (e.applied ? applied : refused).push_back(e.applied ? e.change.task : e.refused);
  }
  void on_redirect(double, const std::string& action, const std::string& rule) override {
    redirects.emplace_back(action, rule);
  }
  std::size_t count(const std::string& what) const {
    return static_cast<std::size_t>(std::count_if(acts.begin(), acts.end(), [&](const Act& a) { return a.what == what; }));
  }
  const Act* first(const std::string& what, const std::string& action = {}) const {
    for (const Act& a : acts)
      if (a.what == what && (action.empty() || a.action == action)) return &a;
    return nullptr;
  }
};

// Steps until the first move has run for `after` seconds; returns its action.
std::string step_into_first_move(ReactiveLoop& loop, const Watch& w, const World& world, double after) {
  while (loop.step()) {
    if (const Watch::Act* s = w.first("start"); s && world.time() >= s->t + after) return s->action;
  }
  return {};
}

// F G all_in_r2, then "o1 and o2 in r2, o1 first": the running move o1 -> r2
// is part of the new plan, so it goes on, and the next move starts within a tick.
TEST(NewTask, ARunningMoveTheNewTaskUsesGoesOnAndTheArmIsNotIdle) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Watch watch;
  loop.add_observer(watch);
  const std::string running = step_into_first_move(loop, watch, w, 0.5);
  ASSERT_FALSE(running.empty());
  const std::string thing = running.substr(5, 2);
  const std::string other = thing == "o1" ? "o2" : "o1";
  loop.set_task(change("F G (\"" + thing + " in r3\" & \"" + other + " in r1\")"));
  const EpisodeMetrics& m = loop.run();
  ASSERT_TRUE(m.success) << m.reason;
  EXPECT_EQ(watch.count("halted"), 0u) << "the running move was stopped";
  EXPECT_TRUE(watch.redirects.empty());
  ASSERT_NE(watch.first("finished", running), nullptr);
  EXPECT_EQ(w.truth().things.at(thing).location, "r3");
  EXPECT_EQ(w.truth().things.at(other).location, "r1");
  EXPECT_EQ(m.actions_succeeded, 1) << "nothing more to do after the running move";
  ASSERT_EQ(m.tasks.size(), 2u);
  EXPECT_EQ(m.tasks[0].outcome, "superseded");
  EXPECT_EQ(m.tasks[1].outcome, "task-done");
  EXPECT_EQ(m.tasks[1].by, "test");
}

TEST(NewTask, TheNextMoveStartsWithinATickOfTheRunningOnesEnd) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  ReactiveLoop loop(w, s, o);
  Watch watch;
  loop.add_observer(watch);
  const std::string running = step_into_first_move(loop, watch, w, 0.5);
  ASSERT_FALSE(running.empty());
  loop.set_task(change("F G all_in_r2"));
  const EpisodeMetrics& m = loop.run();
  ASSERT_TRUE(m.success) << m.reason;
  const Watch::Act* done = watch.first("finished", running);
  ASSERT_NE(done, nullptr) << "the running move (to r3) was not finished";
  // The next move begins at most a tick after the first one ended.
  const Watch::Act* next = nullptr;
  for (const Watch::Act& a : watch.acts)
    if (a.what == "start" && a.t >= done->t && a.action != running) {
      next = &a;
      break;
    }
  ASSERT_NE(next, nullptr);
  EXPECT_LE(next->t - done->t, o.tick_period + 1e-9);
  EXPECT_EQ(w.truth().things.at("o1").location, "r2");
  EXPECT_EQ(w.truth().things.at("o2").location, "r2");
}

// "o1 stays where it is" while o1 is carried away: the move is halted, its
// thing put back, the redirection reported with the rule.
TEST(NewTask, ARunningMoveThatWouldDefeatTheNewTaskIsHaltedAndReported) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Watch watch;
  loop.add_observer(watch);
  const std::string running = step_into_first_move(loop, watch, w, 0.5);
  ASSERT_FALSE(running.empty());
  const std::string thing = running.substr(5, 2);
  const std::string other = thing == "o1" ? "o2" : "o1";
  loop.set_task(change("G \"" + thing + " in r1\" & F G \"" + other + " in r3\""));
  const EpisodeMetrics& m = loop.run();
  ASSERT_TRUE(m.success) << m.reason;
  ASSERT_EQ(watch.redirects.size(), 1u);
  EXPECT_EQ(watch.redirects[0].first, running);
  EXPECT_NE(watch.redirects[0].second.find("no accepting future"), std::string::npos);
  EXPECT_EQ(watch.count("halted"), 1u);
  EXPECT_EQ(w.truth().things.at(thing).location, "r1");
  EXPECT_EQ(w.truth().things.at(other).location, "r3");
  // G: the thing was in r1 in every state of the run since the change.
  for (std::size_t i = loop.task_from(); i < loop.observed_run().size(); ++i)
    EXPECT_EQ(loop.observed_run()[i].things.at(thing).location, "r1") << "state " << i;
}

// A task the current state satisfies: the held block goes back and the episode ends.
TEST(NewTask, ATaskTheCurrentStateSatisfiesEndsTheEpisodeOnceTheArmIsFree) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Watch watch;
  loop.add_observer(watch);
  ASSERT_FALSE(step_into_first_move(loop, watch, w, 0.5).empty());
  const double given = w.time();
  loop.set_task(change("F G all_in_r1"));
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.end, EndReason::TaskDone);
  ASSERT_TRUE(m.completion_time.has_value());
  EXPECT_GE(*m.completion_time, given);
  // The held block was put back (no other move began), then the task was done.
  EXPECT_EQ(watch.count("start"), 1u);
  EXPECT_EQ(watch.count("halted"), 1u);
  ASSERT_EQ(watch.redirects.size(), 1u);
  EXPECT_NE(watch.redirects[0].second.find("satisfies the new task"), std::string::npos);
  EXPECT_EQ(w.truth().things.at("o1").location, "r1");
  EXPECT_EQ(w.truth().things.at("o2").location, "r1");
}

TEST(NewTask, ATaskTheCurrentStateCannotSatisfyEndsUnsatisfiableNamingTheChange) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Watch watch;
  loop.add_observer(watch);
  ASSERT_FALSE(step_into_first_move(loop, watch, w, 0.5).empty());
  loop.set_task(change("G !all_in_r1"));  // every block is in r1 now (the held one counts at its source)
  const EpisodeMetrics& m = loop.run();
  EXPECT_FALSE(m.success);
  EXPECT_EQ(m.end, EndReason::Unsatisfiable) << m.reason;
  EXPECT_NE(m.reason.find("new task"), std::string::npos) << m.reason;
  EXPECT_NE(m.reason.find("by test"), std::string::npos) << m.reason;
  ASSERT_EQ(m.tasks.size(), 2u);
  EXPECT_EQ(m.tasks[1].outcome, "unsatisfiable");
}

// o1 was in r3 before the change (and is in r2 now), but "never in r3" is
// judged from the change on.
TEST(NewTask, TheRunBeforeTheChangeDoesNotCount) {
  const world::Scenario s = scene("F (o1_in_r3 & F G all_in_r2)");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Watch watch;
  loop.add_observer(watch);
  bool visited = false;
  while (loop.step())
    if (const Watch::Act* f = watch.first("finished", "move(o1, r2)"); f && w.time() > f->t) {
      visited = true;
      break;
    }
  ASSERT_TRUE(visited);
  loop.set_task(change("G !o1_in_r3 & F G all_in_r1"));
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(w.truth().things.at("o1").location, "r1");
  EXPECT_GT(loop.task_from(), 0u);
}

TEST(NewTask, CyclesCountForTheTaskInForce) {
  const world::Scenario s = scene("G F o1_in_r2 & G F o1_in_r3", 1);
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  o.cycles = 2;
  ReactiveLoop loop(w, s, o);
  struct Cycles : EpisodeObserver {
    int n = 0;
    void on_cycle(double, int) override { ++n; }
  } cycles;
  loop.add_observer(cycles);
  while (loop.step() && cycles.n < 1) {
  }
  ASSERT_EQ(cycles.n, 1);
  loop.set_task(change("G F o1_in_r1 & G F o1_in_r3"));
  const EpisodeMetrics& m = loop.run();
  ASSERT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.end, EndReason::Cycles);
  EXPECT_EQ(m.cycles, 2);
  ASSERT_EQ(m.tasks.size(), 2u);
  EXPECT_EQ(m.tasks[0].cycles, 1);
  EXPECT_EQ(m.tasks[1].cycles, 2);
  ASSERT_EQ(loop.cycle_marks().size(), 2u);
  EXPECT_GT(loop.cycle_marks()[0], loop.task_from());
  // The new patrol's rounds visit r1.
  bool r1 = false;
  for (std::size_t i = loop.task_from(); i < loop.observed_run().size(); ++i)
    r1 = r1 || loop.observed_run()[i].things.at("o1").location == "r1";
  EXPECT_TRUE(r1);
}

TEST(NewTask, AScheduledTaskTakesEffectAtItsTime) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  o.task_changes = {change("F G all_in_r2", 3.0)};
  ReactiveLoop loop(w, s, o);
  const EpisodeMetrics& m = loop.run();
  ASSERT_TRUE(m.success) << m.reason;
  ASSERT_EQ(m.tasks.size(), 2u);
  EXPECT_GE(m.tasks[1].time, 3.0);
  EXPECT_LE(m.tasks[1].time, 3.0 + o.tick_period);
  EXPECT_EQ(w.truth().things.at("o1").location, "r2");
  EXPECT_EQ(w.truth().things.at("o2").location, "r2");
}

TEST(NewTask, BadScheduledTasksAreRefusedBeforeTheEpisode) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  for (const auto& [task, time, what] : std::vector<std::tuple<std::string, double, std::string>>{
           {"F G nope", 1, "not a proposition"},
           {"F G (", 1, ""},
           {"F G all_in_r2", 400, "ends before it"},
           {"F G all_in_r2", -1, "time must be"},
           {"F G \"o9 in r1\"", 1, "o9"}}) {
    LoopOptions o = inline_options();
    o.task_changes = {change(task, time)};
    try {
      ReactiveLoop loop(w, s, o);
      ADD_FAILURE() << task << " at " << time << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(e.message().find(what), std::string::npos) << e.message();
    }
  }
}

TEST(NewTask, SetTaskRefusesBadTasksAtOnceReportsThemAndTheEpisodeGoesOn) {
  const world::Scenario s = scene("F G all_in_r3");
  SymbolicWorld w(s);
  ReactiveLoop loop(w, s, inline_options());
  Watch watch;
  loop.add_observer(watch);
  ASSERT_TRUE(loop.step());
  EXPECT_THROW(loop.set_task(change("F G nope")), Error);
  EXPECT_THROW(loop.set_task(change("F G &")), Error);
  const EpisodeMetrics& m = loop.run();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(watch.refused.size(), 2u);
  EXPECT_TRUE(watch.applied.empty());
  ASSERT_EQ(m.tasks.size(), 1u);
  EXPECT_EQ(w.truth().things.at("o1").location, "r3");
  EXPECT_THROW(loop.set_task(change("F G all_in_r1")), Error) << "after the end";
}

TEST(NewTask, SetTaskIsSafeFromAnotherThread) {
  const world::Scenario s = scene("F G all_in_r3", 3);
  SymbolicWorld w(s);
  LoopOptions o = inline_options();
  o.planning = PlanningMode::Worker;
  ReactiveLoop loop(w, s, o);
  struct Clock : EpisodeObserver {
    std::atomic<bool> reached{false};
    void on_tick(double t, bt::Status, const std::string&) override {
      if (t >= 2.0) reached.store(true);
    }
    void on_end(double, const EpisodeMetrics&, const world::Placement&) override { reached.store(true); }
  } clock;
  loop.add_observer(clock);
  std::thread person([&] {
    while (!clock.reached.load()) std::this_thread::yield();
    try {
      loop.set_task(change("F G all_in_r2"));
    } catch (const Error&) {  // the episode ended first: nothing to check
    }
  });
  const EpisodeMetrics& m = loop.run();
  person.join();
  ASSERT_TRUE(m.success) << m.reason;
  if (m.tasks.size() == 2) {
    EXPECT_EQ(w.truth().things.at("o3").location, "r2");
  }
}

}  // namespace
}  // namespace rtamp::exec
