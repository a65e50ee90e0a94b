// Whole episodes of the reactive loop (Algorithm 1) on the simulated UR5:
// the scripted demo scenario, an object taken out of the gripper (put back
// elsewhere, or taken away), a change that makes the task unsatisfiable, and a
// recurring task that runs until the time limit.
// Each checks the outcome and that the JSON Lines log is complete: every line
// parses, it starts with "episode" and ends with "end", and it records the
// interventions, plans, tree changes and actions.
#include "rtamp/episode/episode.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {
namespace {

struct Log {
  std::vector<nlohmann::json> lines;
  std::vector<nlohmann::json> of(const std::string& ev) const {
    std::vector<nlohmann::json> out;
    for (const auto& j : lines)
      if (j.at("ev") == ev) out.push_back(j);
    return out;
  }
};

Log read_log(const std::string& path) {
  Log log;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) log.lines.push_back(nlohmann::json::parse(line));  // throws if malformed
  return log;
}

std::string log_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rtamp_episode_test_" + name + ".jsonl")).string();  // one per test
}

void expect_complete(const Log& log, const EpisodeMetrics& m) {
  ASSERT_GE(log.lines.size(), 2u);
  EXPECT_EQ(log.lines.front().at("ev"), "episode");
  EXPECT_EQ(log.lines.back().at("ev"), "end");
  EXPECT_EQ(log.lines.back().at("success"), m.success);
  EXPECT_EQ(log.lines.back().at("reason"), m.reason);
  EXPECT_FALSE(log.of("plan").empty());
  EXPECT_FALSE(log.of("tree").empty());
  // Every started action finished, failed or was halted.
  std::size_t started = 0, ended = 0;
  for (const auto& a : log.of("action")) {
    if (a.at("what") == "start") ++started;
    if (a.at("what") == "finished" || a.at("what") == "failed" || a.at("what") == "halted") ++ended;
  }
  EXPECT_GE(started, ended);
  EXPECT_LE(started, ended + 1);  // at most the last one was cut by the end of the episode
  // Time never runs backwards.
  double t = 0;
  for (const auto& j : log.lines) {
    EXPECT_GE(j.at("t").get<double>(), t - 1e-9);
    t = j.at("t").get<double>();
  }
}

EpisodeOptions options(const std::string& name) {
  EpisodeOptions o;
  o.outputs.log = log_path(name);
  o.loop.max_time = 300;
  return o;
}

TEST(Episode, ScriptedTrayScenarioSucceedsWithACompleteLog) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const EpisodeOptions o = options("tray");
  const EpisodeMetrics m = run_episode(s, o);
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.reason, "task done");
  EXPECT_EQ(m.interventions, 1);
  ASSERT_TRUE(m.completion_time.has_value());
  EXPECT_GT(*m.completion_time, 0);
  EXPECT_GT(m.motion_cost, 0);
  EXPECT_GE(m.actions_succeeded, 7);  // load the tray, carry it, unload it, redo o2
  const Log log = read_log(o.outputs.log);
  expect_complete(log, m);
  ASSERT_EQ(log.of("intervention").size(), 1u);
  EXPECT_EQ(log.of("intervention")[0].at("kind"), "relocate");
  EXPECT_EQ(log.of("intervention")[0].at("applied"), true);
  // The first plan uses the tray.
  const auto first = log.of("plan").front();
  EXPECT_EQ(first.at("first"), true);
  EXPECT_NE(first.at("actions").dump().find("move(r3, r2)"), std::string::npos);
  // At the end every block is in r2.
  const auto& placement = log.lines.back().at("placement");
  for (const char* b : {"o1", "o2", "o3"}) EXPECT_EQ(placement.at(b), "r2") << b;
  std::filesystem::remove(o.outputs.log);
}

// The demo: a tray handed over mid-task. The robot finishes the move it is
// making, then switches to the tray plan (the tree change waits for that move
// and goes in before the next one starts) and completes the task.
TEST(Episode, HandedOverTrayIsUsedOnceTheRunningMoveEnds) {
  const world::Scenario s = world::load_scenario("3-block-tray-handover");
  const EpisodeOptions o = options("handover");
  const EpisodeMetrics m = run_episode(s, o);
  EXPECT_TRUE(m.success) << m.reason;
  const Log log = read_log(o.outputs.log);
  expect_complete(log, m);
  const auto plans = log.of("plan");
  ASSERT_GE(plans.size(), 2u);
  EXPECT_EQ(plans[0].at("actions").dump().find("r3"), std::string::npos) << "no tray at first";
  EXPECT_NE(plans[1].at("actions").dump().find("move(r3, r2)"), std::string::npos) << "the replan uses the tray";
  // The first move started after the handover is a move into the tray.
  std::vector<std::string> started;
  for (const auto& a : log.of("action"))
    if (a.at("what") == "start") started.push_back(a.at("action"));
  ASSERT_GE(started.size(), 2u);
  EXPECT_EQ(started[0], "move(o1, r2)");
  EXPECT_NE(started[1].find(", r3)"), std::string::npos) << started[1];
  EXPECT_NE(std::find(started.begin(), started.end(), "move(r3, r2)"), started.end());
  std::filesystem::remove(o.outputs.log);
}

// The same seed gives the same episode — with inline planning: a planner on
// its worker thread charges its wall time to world time, which depends on the
// machine's load (docs/cli.md --planning).
TEST(Episode, IsDeterministicForASeed) {
  const world::Scenario s = world::load_scenario("3-block");
  EpisodeOptions o;
  o.seed = 5;
  o.loop.planning = exec::PlanningMode::Inline;
  o.person.change = world::RandomChange{world::Intervention::Kind::Relocate};
  const EpisodeMetrics a = run_episode(s, o), b = run_episode(s, o);
  EXPECT_EQ(a.success, b.success);
  EXPECT_EQ(a.completion_time, b.completion_time);
  EXPECT_EQ(a.motion_cost, b.motion_cost);
  EXPECT_EQ(a.replans, b.replans);
  EXPECT_EQ(a.tree_changes, b.tree_changes);
}

world::Intervention take_from_gripper(double time, const std::string& to) {
  world::Intervention iv;
  iv.kind = world::Intervention::Kind::TakeFromGripper;
  iv.time = time;
  iv.location = to;
  return iv;
}

// The operator takes the block out of the gripper while it is carried and puts
// it back in r1: the move fails, the tree or the planner redoes it.
TEST(Episode, ObjectTakenFromTheGripperAndPutBackIsMovedAgain) {
  world::Scenario s = world::load_scenario("3-block");
  s.interventions = {take_from_gripper(4.0, "r1")};
  const EpisodeOptions o = options("take_back");
  const EpisodeMetrics m = run_episode(s, o);
  EXPECT_TRUE(m.success) << m.reason;
  const Log log = read_log(o.outputs.log);
  expect_complete(log, m);
  ASSERT_EQ(log.of("intervention").size(), 1u);
  EXPECT_EQ(log.of("intervention")[0].at("applied"), true) << "the gripper held nothing at t = 4 s";
  EXPECT_EQ(log.of("intervention")[0].at("kind"), "take-from-gripper");
  EXPECT_GE(m.actions_failed, 1);
  for (const char* b : {"o1", "o2", "o3"}) EXPECT_EQ(log.lines.back().at("placement").at(b), "r2") << b;
  std::filesystem::remove(o.outputs.log);
}

// Taken away for good: the task is about the blocks that are left.
TEST(Episode, ObjectTakenFromTheGripperForGoodIsForgotten) {
  world::Scenario s = world::load_scenario("3-block");
  s.interventions = {take_from_gripper(4.0, "")};
  const EpisodeOptions o = options("take_away");
  const EpisodeMetrics m = run_episode(s, o);
  EXPECT_TRUE(m.success) << m.reason;
  const Log log = read_log(o.outputs.log);
  expect_complete(log, m);
  EXPECT_EQ(log.of("intervention").at(0).at("applied"), true);
  EXPECT_EQ(log.lines.back().at("placement").size(), 2u);
  std::filesystem::remove(o.outputs.log);
}

// r2 holds at most three things; a fourth block makes "all blocks in r2"
// impossible. The episode ends at once with the planner's reason.
TEST(Episode, UnsatisfiableChangeEndsWithAClearReason) {
  world::Scenario s = world::load_scenario("3-block");
  for (auto& r : s.regions)
    if (r.name == "r2") r.capacity = 3;
  world::Intervention add;
  add.kind = world::Intervention::Kind::Add;
  add.time = 3;
  add.subject = "o4";
  add.cls = "block";
  add.location = "r1";
  s.interventions = {add};
  const EpisodeOptions o = options("unsat");
  const EpisodeMetrics m = run_episode(s, o);
  EXPECT_FALSE(m.success);
  EXPECT_NE(m.reason.find("no plan"), std::string::npos) << m.reason;
  EXPECT_NE(m.reason.find("capacit"), std::string::npos) << m.reason;
  EXPECT_FALSE(m.completion_time.has_value());
  EXPECT_EQ(m.end, exec::EndReason::NoPlan);
  const Log log = read_log(o.outputs.log);
  expect_complete(log, m);
  EXPECT_EQ(log.lines.back().at("end"), "no-plan");
  EXPECT_TRUE(log.lines.back().at("metrics").at("completion_time").is_null());
  std::filesystem::remove(o.outputs.log);
}

// A recurring task (patrol o1 between r1 and r2) has a plan whose cycle moves
// the block: the robot keeps going until the time limit, which says why.
TEST(Episode, RecurringTaskRunsUntilTheTimeLimitAndSaysWhy) {
  world::Scenario s = world::load_scenario("3-block");
  for (const char* r : {"r1", "r2"}) {
    world::Proposition prop;
    prop.name = std::string("o1_in_") + r;
    prop.text = std::string("o1 in ") + r;
    prop.expr = world::parse_prop_expr(prop.text);
    s.propositions.push_back(prop);
  }
  s.task = "G F o1_in_r1 & G F o1_in_r2";
  s.interventions.clear();
  EpisodeOptions o = options("patrol");
  o.loop.max_time = 40;
  const EpisodeMetrics m = run_episode(s, o);
  EXPECT_FALSE(m.success);
  EXPECT_NE(m.reason.find("time limit"), std::string::npos) << m.reason;
  EXPECT_NE(m.reason.find("recurring task"), std::string::npos) << m.reason;
  const Log log = read_log(o.outputs.log);
  expect_complete(log, m);
  // o1 went to r2 and back at least once.
  std::size_t to_r2 = 0, to_r1 = 0;
  for (const auto& a : log.of("action"))
    if (a.at("what") == "finished") {
      if (a.at("action") == "move(o1, r2)") ++to_r2;
      if (a.at("action") == "move(o1, r1)") ++to_r1;
    }
  EXPECT_GE(to_r2, 1u);
  EXPECT_GE(to_r1, 1u);
  std::filesystem::remove(o.outputs.log);
}

TEST(Episode, UnreadableLogPathIsAClearError) {
  EpisodeOptions o;
  o.outputs.log = "/nonexistent-dir/episode.jsonl";
  EXPECT_THROW(run_episode(world::load_scenario("3-block"), o), Error);
}

}  // namespace
}  // namespace rtamp::episode
