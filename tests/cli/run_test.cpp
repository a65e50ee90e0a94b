// `rtamp run` (one episode) and `rtamp plan --cost ik` through the built binary:
// exit codes, the --json metrics, the JSON Lines log, the tree files, errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "run_cli.hpp"

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
