// `rtamp run` (one episode) and `rtamp plan --cost ik` through the built binary:
// exit codes, the --json metrics, the JSON Lines log, the tree files, errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "run_cli.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::cli::testing {
namespace {

TEST(CliRun, EpisodeSucceedsAndPrintsMetricsAsJson) {
  const Result r = run("run 3-block-tray --quiet --json");
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("success"), true);
  EXPECT_EQ(j.at("reason"), "task done");
  EXPECT_GT(j.at("completion_time").get<double>(), 0);
  EXPECT_GE(j.at("tree_changes").get<int>(), 7);
}

TEST(CliRun, TimelineLogAndTrees) {
  const auto dir = scratch();
  const std::string log = (dir / "episode.jsonl").string(), trees = (dir / "trees").string();
  const Result r = run("run 3-block --log '" + log + "' --trees '" + trees + "'");
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("first plan in"), std::string::npos);
  EXPECT_NE(r.out.find("start move(o1, r2)"), std::string::npos);
  EXPECT_NE(r.out.find("SUCCESS: task done"), std::string::npos);
  std::istringstream in(slurp(log));
  std::string line, last;
  int lines = 0;
  while (std::getline(in, line)) {
    EXPECT_TRUE(nlohmann::json::accept(line)) << line;
    last = line;
    ++lines;
  }
  EXPECT_GT(lines, 100);
  EXPECT_EQ(nlohmann::json::parse(last).at("ev"), "end");
  const std::string xml = slurp(std::filesystem::path(trees) / "tree_000.xml");
  EXPECT_NE(xml.find("<root BTCPP_format=\"4\""), std::string::npos);
  EXPECT_NE(xml.find("<TreeNodesModel>"), std::string::npos);
}

TEST(CliRun, TimeLimitIsAFailureWithItsReason) {
  const Result r = run("run 3-block --max-time 3 --quiet --json");
  EXPECT_EQ(r.rc, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("success"), false);
  EXPECT_NE(j.at("reason").get<std::string>().find("time limit"), std::string::npos);
}

TEST(CliRun, BadInputIsOneClearLine) {
  Result r = run("run no-such-scenario");
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("rtamp: error:"), std::string::npos);
  EXPECT_NE(r.err.find("no-such-scenario"), std::string::npos);
  r = run("run 3-block --bt sideways");
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find("--bt"), std::string::npos);
  r = run("run --help");
  EXPECT_EQ(r.rc, 0);
  EXPECT_NE(r.out.find("online-action"), std::string::npos);
}

TEST(CliRun, SymbolicWorldRunsTheTrayTask) {
  const Result r = run("run 3-block-tray --world symbolic --json");
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // only JSON on stdout, the timeline went to stderr
  EXPECT_EQ(j.at("success"), true);
  EXPECT_EQ(j.at("end"), "task-done");
  EXPECT_EQ(j.at("interventions_applied"), 1);
  EXPECT_NE(r.err.find("first plan in"), std::string::npos);
}

TEST(CliRun, PlanRecordsCarryEachMovesCost) {
  // The page's plan panel shows each move's cost: the plan record's `costs` (one per
  // action) add up to the plan's `cost`, and `in_cycle` has one flag per action.
  const auto dir = scratch();
  const std::string log = (dir / "tray.jsonl").string();
  const Result r = run("run 3-block-tray --world symbolic --quiet --log '" + log + "'");
  ASSERT_EQ(r.rc, 0) << r.err;
  std::istringstream in(slurp(log));
  std::string line;
  int plans = 0;
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line);
    if (j.at("ev") != "plan") continue;
    ++plans;
    const auto& actions = j.at("actions");
    ASSERT_EQ(j.at("costs").size(), actions.size());
    ASSERT_EQ(j.at("in_cycle").size(), actions.size());
    double sum = 0;
    for (const auto& c : j.at("costs")) sum += c.get<double>();
    EXPECT_NEAR(sum, j.at("cost").get<double>(), 1e-9 * (1 + sum)) << line;
  }
  EXPECT_GE(plans, 1);
}

TEST(CliRun, FailedEpisodeHasNoCompletionTime) {
  const Result r = run("run 3-block --world symbolic --max-time 3 --quiet --json");
  EXPECT_EQ(r.rc, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("end"), "time-limit");
  EXPECT_TRUE(j.at("completion_time").is_null());
}

// SIGINT ends the episode cleanly: exit 130 and a log that ends with its "end" record.
TEST(CliRun, InterruptWritesTheEndRecord) {
  const auto dir = scratch();
  const std::string log = (dir / "interrupted.jsonl").string();
  for (const auto& [sig, code] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    std::filesystem::remove(log);
    // The signal arrives as soon as the log has its first record: the episode has
    // started (on an idle machine the whole MuJoCo episode takes under a second of
    // wall time, so a fixed sleep of one second could come after its end).
    const Result r = run("run 3-block --quiet --log '" + log + "' & pid=$!; until [ -s '" + log +
                         "' ]; do sleep 0.01; done; kill -" + std::string(sig) + " $pid; wait $pid");
    EXPECT_EQ(r.rc, code) << sig << ": " << r.err;
    std::istringstream in(slurp(log));
    std::string line, last;
    while (std::getline(in, line)) last = line;
    ASSERT_FALSE(last.empty()) << sig;
    const auto end = nlohmann::json::parse(last);
    EXPECT_EQ(end.at("ev"), "end");
    EXPECT_EQ(end.at("end"), "interrupted");
    EXPECT_TRUE(end.at("metrics").at("completion_time").is_null());
  }
}

TEST(CliRun, PatrolWithCyclesSucceeds) {
  const auto dir = scratch();
  const std::string yaml = (dir / "patrol.yaml").string();
  std::string text = slurp(std::string(RTAMP_SOURCE_DIR) + "/scenarios/3-block.yaml");
  text.replace(text.find("propositions:"), std::string::npos,
               "propositions:\n  o1_in_r1: \"o1 in r1\"\n  o1_in_r2: \"o1 in r2\"\ntask: \"G F o1_in_r1 & G F o1_in_r2\"\n");
  std::ofstream(yaml) << text;
  const Result r = run("run '" + yaml + "' --world symbolic --cycles 2 --quiet --json");
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("end"), "cycles");
  EXPECT_EQ(j.at("cycles"), 2);
}

TEST(CliPlan, IkCostModelPlansTheTrayTask) {
  const Result r = run("plan 3-block-tray --cost ik --json");
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("cost_model"), "ik");
  const auto& p = j.at("plans").at(0);
  EXPECT_EQ(p.at("found"), true);
  EXPECT_GT(p.at("cost").get<double>(), 0);
  // The skills' tool paths make carrying the blocks on the tray the cheaper plan here too.
  EXPECT_NE(p.dump().find("move(r3, r2)"), std::string::npos);
}

}  // namespace
}  // namespace rtamp::cli::testing
