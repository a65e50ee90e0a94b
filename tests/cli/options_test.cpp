// The rtamp command line speaking with one voice, through the built binary:
// numeric options within their documented ranges (inf where a time limit may
// be unlimited, seeds unsigned 64-bit), names from the planner's registry with
// a did-you-mean, output files checked before anything runs, the argument
// parser's and unknown-command errors in the `rtamp: error: ...` form with
// exit 2, control bytes escaped, and --json writing only JSON on stdout;
// `plan --transition-based` reports its automaton's acceptance and plans at
// the state-based costs.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "run_cli.hpp"

namespace rtamp::cli::testing {
namespace {

// One line on stderr, in the documented form, naming `where`; exit 2.
void expect_refused(const Result& r, const std::string& where, const std::string& cmd) {
  EXPECT_EQ(r.rc, 2) << cmd << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("rtamp: error: ", 0), 0u) << cmd << "\n" << r.err;
  EXPECT_NE(r.err.find(where), std::string::npos) << cmd << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << cmd << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << cmd << "\n" << r.out;
}

TEST(CliOptions, NumbersOutsideTheirRangesAreRefused) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"plan 3-block --time-limit 0", "--time-limit"},
      {"plan 3-block --time-limit -1", "--time-limit"},
      {"plan 3-block --time-limit nan", "--time-limit"},
      {"plan 3-block --time-limit 5s", "--time-limit"},
      {"plan 3-block --time-limit ''", "--time-limit"},
      {"plan 3-block --max-nodes -1", "--max-nodes"},
      {"plan 3-block --max-nodes 0", "--max-nodes"},
      {"plan 3-block --max-nodes 1.5", "--max-nodes"},
      {"plan 3-block --max-nodes 99999999999999999999999", "--max-nodes"},
      {"plan 3-block --max-memory 0", "--max-memory"},
      {"plan 3-block --max-memory -1", "--max-memory"},
      {"plan 3-block --max-memory nan", "--max-memory"},
      {"plan 3-block --max-memory 4GiB", "--max-memory"},
      {"run 3-block --world symbolic --max-time nan", "--max-time"},
      {"run 3-block --world symbolic --max-time -5", "--max-time"},
      {"run 3-block --world symbolic --max-time 0", "--max-time"},
      {"run 3-block --world symbolic --max-time inf", "--max-time"},
      {"run 3-block --world symbolic --seed -1", "--seed"},
      {"run 3-block --world symbolic --seed 18446744073709551616", "--seed"},
      {"run 3-block --world symbolic --seed 1e3", "--seed"},
      {"run 3-block --world symbolic --rate 101", "--rate"},
      {"run 3-block --world symbolic --failures 1.5", "--failures"},
      {"run 3-block --world symbolic --cycles -1", "--cycles"},
      {"run 3-block --perception camera --mcap-image-period -1", "--mcap-image-period"},
      {"run 3-block --perception camera --mcap-image-period nan", "--mcap-image-period"},
      {"run 3-block --perception camera --mcap-image-period 1s", "--mcap-image-period"},
      {"run 3-block --perception camera --mcap-image-period ''", "--mcap-image-period"},
      {"batch 3-block --perception camera --mcap-image-period -0.5", "--mcap-image-period"},
      {"batch 3-block --perception camera --mcap-image-period garbage", "--mcap-image-period"},
      {"batch 3-block --world symbolic --trials 0", "--trials"},
      {"batch 3-block --world symbolic --jobs 0", "--jobs"},
      {"batch 3-block --world symbolic --seed +1", "--seed"},
      {"gen --regions 0", "--regions"},
      {"gen --objects 257", "--objects"},
      {"gen --seed -3", "--seed"},
      {"sim 3-block --width 8", "--width"},
      {"sim 3-block --noise inf", "--noise"},
  };
  for (const auto& [cmd, where] : cases) expect_refused(run(cmd), where, cmd);
  // The message says what is allowed, with numbers written plainly.
  const Result r = run("run 3-block --world symbolic --max-time 0");
  EXPECT_NE(r.err.find("must be in (0, 10000000]"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("000000 "), std::string::npos) << r.err;
}

TEST(CliOptions, InfiniteAndHugeTimeLimitsMeanNoLimit) {
  for (const std::string limit : {"inf", "1e10", "Infinity"}) {
    const Result r = run("plan 3-block-tray --time-limit " + limit + " --json");
    ASSERT_EQ(r.rc, 0) << limit << "\n" << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["plans"][0]["found"], true) << limit;
    EXPECT_EQ(j["plans"][0]["stats"]["hit_time_limit"], false) << limit;
  }
}

// --max-memory is in GiB; a query over it stops with its own reason, inf is no limit.
TEST(CliOptions, TheMemoryLimitStopsAQueryWithItsOwnReason) {
  const Result r = run("plan 3-block-tray --graph full --max-memory 1e-6 --json");  // about 1 KiB
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["plans"][0]["found"], false) << r.out;
  EXPECT_EQ(j["plans"][0]["reason"], "memory-limit") << r.out;
  EXPECT_EQ(j["plans"][0]["stats"]["hit_memory_limit"], true) << r.out;
  const Result unlimited = run("plan 3-block-tray --graph full --max-memory inf --json");
  ASSERT_EQ(unlimited.rc, 0) << unlimited.err;
  EXPECT_EQ(nlohmann::json::parse(unlimited.out)["plans"][0]["found"], true);
}

// The same plans (costs, replans after a change) from either automaton; on a
// generated patrol of 8 blocks, no more expansions than state-based.
TEST(CliOptions, TransitionBasedPlansAtTheSameCosts) {
  const std::string patrol = (scratch() / "patrol8.yaml").string();
  ASSERT_EQ(run("gen -m 5 -n 8 --layout line --task 'G F all_in_r2 & G F all_in_r3' --prop 'all_in_r3=all block in r3' "
                "-o " + patrol).rc, 0);
  for (const std::string& args : std::vector<std::string>{"3-block-tray --change 'move o1 r3'", patrol + " --algo astar"}) {
    SCOPED_TRACE(args);
    const Result s = run("plan --json " + args);
    const Result t = run("plan --json --transition-based " + args);
    ASSERT_EQ(s.rc, 0) << s.err;
    ASSERT_EQ(t.rc, 0) << t.err;
    const auto js = nlohmann::json::parse(s.out), jt = nlohmann::json::parse(t.out);
    EXPECT_EQ(js["automaton_acceptance"], "state");
    EXPECT_EQ(jt["automaton_acceptance"], "transition");
    ASSERT_EQ(js["plans"].size(), jt["plans"].size());
    for (std::size_t i = 0; i < js["plans"].size(); ++i) {
      ASSERT_EQ(jt["plans"][i]["found"], true);
      EXPECT_NEAR(jt["plans"][i]["cost"].get<double>(), js["plans"][i]["cost"].get<double>(), 1e-9);
    }
    if (args != patrol + " --algo astar") continue;
    EXPECT_LT(jt["automaton_states"].get<int>(), js["automaton_states"].get<int>());
    EXPECT_LE(jt["plans"][0]["stats"]["expanded"].get<int>(), js["plans"][0]["stats"]["expanded"].get<int>());
  }
  const Result text = run("plan 3-block --transition-based");
  ASSERT_EQ(text.rc, 0) << text.err;
  EXPECT_NE(text.out.find("-state transition-based Büchi automaton)"), std::string::npos) << text.out;
  expect_refused(run("plan 3-block --transition-based=maybe"), "--transition-based", "--transition-based=maybe");
  // Generalized where it pays: Dijkstra on the patrol's one-state, two-set automaton.
  const Result d = run("plan --json --transition-based --algo dijkstra " + patrol);
  const Result d1 = run("plan --json --transition-based --generalized never --algo dijkstra " + patrol);
  ASSERT_EQ(d.rc, 0) << d.err;
  ASSERT_EQ(d1.rc, 0) << d1.err;
  const auto jd = nlohmann::json::parse(d.out), jd1 = nlohmann::json::parse(d1.out);
  EXPECT_EQ(jd["automaton_acceptance"], "generalized");
  EXPECT_EQ(jd["automaton_sets"], 2);
  EXPECT_EQ(jd["automaton_states"], 1);
  EXPECT_EQ(jd1["automaton_acceptance"], "transition");
  EXPECT_NEAR(jd["plans"][0]["cost"].get<double>(), jd1["plans"][0]["cost"].get<double>(), 1e-9);
  EXPECT_LT(jd["plans"][0]["stats"]["expanded"].get<int>(), jd1["plans"][0]["stats"]["expanded"].get<int>());
  const Result dt = run("plan --transition-based --algo dijkstra " + patrol);
  EXPECT_NE(dt.out.find("1-state transition-based generalized (2 sets) Büchi automaton)"), std::string::npos) << dt.out;
  expect_refused(run("plan 3-block --transition-based --generalized maybe"), "--generalized", "maybe");
  expect_refused(run("plan 3-block --generalized always"), "--generalized always", "--transition-based");
}

TEST(CliOptions, TheLargestSeedIsAccepted) {
  const Result r = run("run 3-block --world symbolic --quiet --json --seed 18446744073709551615");
  ASSERT_NE(r.rc, 2) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("seed").get<std::uint64_t>(), 18446744073709551615ull);
}

TEST(CliOptions, RegistryNamesWithDidYouMean) {
  Result r = run("plan 3-block --algo astr");
  expect_refused(r, "--algo", "--algo astr");
  EXPECT_NE(r.err.find("did you mean 'astar'?"), std::string::npos) << r.err;
  r = run("run 3-block --cost eucild");
  expect_refused(r, "--cost", "--cost eucild");
  EXPECT_NE(r.err.find("did you mean 'euclid'?"), std::string::npos) << r.err;
  r = run("batch 3-block --algo astar --algo dijkstr");
  expect_refused(r, "--algo", "--algo dijkstr");
  EXPECT_NE(r.err.find("did you mean 'dijkstra'?"), std::string::npos) << r.err;
  // --help lists every registered name with its description, and every built-in scenario.
  r = run("plan --help");
  ASSERT_EQ(r.rc, 0);
  for (const char* s : {"astar-exp:", "dijkstra:", "euclid:", "unit:", "ik:", "inverse kinematics", "3-block-tray-handover"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST(CliOptions, CommandsAndParserErrorsSpeakLikeTheRest) {
  Result r = run("foo");
  expect_refused(r, "unknown command 'foo'", "foo");
  r = run("plna 3-block");
  expect_refused(r, "did you mean 'plan'?", "plna");
  r = run("");
  expect_refused(r, "no command given", "(none)");
  r = run("plan 3-block --bogus");
  expect_refused(r, "unknown option '--bogus'", "--bogus");
  r = run("plan");
  expect_refused(r, "scenario is required", "plan");
  r = run("plan 3-block --time-limit");
  expect_refused(r, "--time-limit", "--time-limit without a value");
  EXPECT_EQ(run("--help").rc, 0);
  EXPECT_EQ(run("--version").rc, 0);
}

TEST(CliOptions, ControlBytesAreEscaped) {
  const Result r = run("plan \"$(printf 'no\\033[2Jsuch\\007')\"");
  EXPECT_EQ(r.rc, 2);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x1b[2Jsuch\\x07"), std::string::npos) << r.err;
}

TEST(CliOptions, OutputFilesAreCheckedBeforeAnythingRuns) {
  namespace fs = std::filesystem;
  const fs::path dir = scratch() / "outputs";
  fs::create_directories(dir);
  const std::string missing = (dir / "no-such-dir" / "x").string();
  struct Case {
    std::string cmd, where;
  };
  const std::vector<Case> cases = {
      {"run 3-block --video '" + missing + ".mp4'", "--video"},
      {"run 3-block --video '" + dir.string() + "'", "--video"},
      {"sim 3-block --do 'move o1 r2' --video '" + missing + ".mp4'", "--video"},
      {"sim 3-block --do 'move o1 r2' --snapshot '" + missing + ".png'", "--snapshot"},
      {"gen -o '" + missing + ".yaml'", "--output"},
      {"gen -o '" + dir.string() + "'", "--output"},
      {"batch 3-block --world symbolic --trials 1 -o '" + missing + ".csv'", "--output"},
      {"batch 3-block --world symbolic --trials 1 -o '" + dir.string() + "'", "--output"},
      {"ltl2ba -F '" + dir.string() + "'", "is a directory"},
  };
  for (const auto& c : cases) {
    const Result r = run(c.cmd);
    expect_refused(r, c.where, c.cmd);
  }
  // --trees to a place that cannot be a directory: refused before the episode (no timeline).
  const std::string file = write_file("not_a_dir", "x");
  const Result r = run("run 3-block --world symbolic --trees '" + file + "/trees'");
  EXPECT_EQ(r.rc, 2) << r.err;
  EXPECT_EQ(r.out.find("first plan"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "no-such-dir"));
  // batch --log-dir: a file, or a path below a file, is refused before any trial runs.
  for (const std::string& logs : {file, file + "/logs"}) {
    const std::string cmd = "batch 3-block --world symbolic --trials 1 --log-dir '" + logs + "'";
    expect_refused(run(cmd), "--log-dir", cmd);
  }
  // A directory that does not exist yet is fine: the batch creates it.
  const std::string fresh = (dir / "logs" / "deeper").string();
  const Result ok = run("batch 3-block --world symbolic --trials 1 --log-dir '" + fresh + "'");
  EXPECT_EQ(ok.rc, 0) << ok.err;
  EXPECT_TRUE(fs::is_directory(fresh));
}

TEST(CliOptions, JsonMeansOnlyJsonOnStdout) {
  const std::string csv = (scratch() / "json.csv").string();
  const std::vector<std::string> cmds = {
      "plan 3-block --json", "run 3-block --world symbolic --json",
      "run 3-block-tray --world symbolic --json --rate 0.2 --seed 3",
      "batch 3-block --world symbolic --trials 1 --algo astar --change none --json -o '" + csv + "'"};
  for (const std::string& cmd : cmds) {
    const Result r = run(cmd);
    EXPECT_NE(r.rc, 2) << cmd << "\n" << r.err;
    EXPECT_TRUE(nlohmann::json::accept(r.out)) << cmd << "\n" << r.out;
  }
}

}  // namespace
}  // namespace rtamp::cli::testing
