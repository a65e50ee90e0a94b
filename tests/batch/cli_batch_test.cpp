// `rtamp batch` through the built binary: --merge on synthetic CSVs (joins,
// sorts, refuses duplicates and header mismatches, exit codes) and usage
// errors. Real episodes: cli_batch_slow_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../cli/run_cli.hpp"
#include "rtamp/batch/csv.hpp"
#include "rtamp/batch/trials.hpp"

namespace {

using namespace rtamp::batch;
namespace ct = rtamp::cli::testing;

EpisodeRecord rec(const std::string& algo, const std::string& change, int trial, double completion) {
  EpisodeRecord r;
  r.scenario = "3-block-tray";
  r.algorithm = algo;
  r.bt = "online-action";
  r.change = change;
  r.trial = trial;
  r.seed = trial_seed(trial, 1);
  r.success = true;
  r.reason = "task done";
  r.first_plan_s = 0.001;
  r.completion_s = completion;
  r.replans = trial;
  return r;
}

std::string csv_text(const std::vector<EpisodeRecord>& rs) {
  std::ostringstream o;
  write_csv(o, rs);
  return o.str();
}

TEST(CliBatch, MergeJoinsSortsAndSummarizes) {
  const std::string a = ct::write_file("m_a.csv", csv_text({rec("dijkstra", "add", 2, 300), rec("astar", "relocate", 1, 200)}));
  const std::string b = ct::write_file("m_b.csv", csv_text({rec("astar", "relocate", 2, 210), rec("dijkstra", "add", 1, 310)}));
  const std::string out = (ct::scratch() / "m_out.csv").string();
  const auto r = ct::run("batch --merge '" + a + "' '" + b + "' -o '" + out + "' --json");
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["episodes"], 4);
  ASSERT_EQ(j["rows"].size(), 2u);
  EXPECT_EQ(j["rows"][0]["change"], "relocate");
  EXPECT_DOUBLE_EQ(j["rows"][0]["completion_s"]["mean"].get<double>(), 205);
  EXPECT_DOUBLE_EQ(j["rows"][1]["completion_s"]["mean"].get<double>(), 305);
  const auto merged = read_csv_file(out);
  ASSERT_EQ(merged.size(), 4u);
  EXPECT_TRUE(std::is_sorted(merged.begin(), merged.end(), canonical_less));
  EXPECT_EQ(merged[0], rec("astar", "relocate", 1, 200));
  // Row selection with --algo.
  const auto sel = ct::run("batch --merge '" + a + "' '" + b + "' --algo dijkstra --format tsv");
  ASSERT_EQ(sel.rc, 0) << sel.err;
  EXPECT_EQ(std::count(sel.out.begin(), sel.out.end(), '\n'), 2) << sel.out;  // header + one cell
  EXPECT_NE(sel.out.find("\tdijkstra\t"), std::string::npos);
  // Text table by default.
  const auto text = ct::run("batch --merge '" + a + "'");
  ASSERT_EQ(text.rc, 0) << text.err;
  EXPECT_NE(text.out.find("Completion time (s)"), std::string::npos);
  EXPECT_NE(text.out.find("1/1"), std::string::npos);
}

TEST(CliBatch, MergeRefusesDuplicatesAndHeaderMismatch) {
  const std::string a = ct::write_file("d_a.csv", csv_text({rec("astar", "relocate", 1, 200)}));
  const auto dup = ct::run("batch --merge '" + a + "' '" + a + "'");
  EXPECT_EQ(dup.rc, 2);
  EXPECT_NE(dup.err.find("duplicate"), std::string::npos) << dup.err;
  std::string other = csv_text({rec("astar", "relocate", 2, 200)});
  other.replace(0, 8, "scene   ");
  const std::string b = ct::write_file("d_b.csv", other);
  const auto hdr = ct::run("batch --merge '" + a + "' '" + b + "'");
  EXPECT_EQ(hdr.rc, 2);
  EXPECT_NE(hdr.err.find("header differs"), std::string::npos) << hdr.err;
  const auto missing = ct::run("batch --merge /nonexistent/x.csv");
  EXPECT_EQ(missing.rc, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos) << missing.err;
}

TEST(CliBatch, UsageErrors) {
  const auto shard = ct::run("batch 3-block-tray --shard 5/4 --trials 1");
  EXPECT_EQ(shard.rc, 2);
  EXPECT_NE(shard.err.find("bad shard '5/4'"), std::string::npos) << shard.err;
  const auto none = ct::run("batch");
  EXPECT_EQ(none.rc, 2);
  const auto both = ct::run("batch 3-block-tray --merge x.csv");
  EXPECT_EQ(both.rc, 2);
  const auto group = ct::run("batch 3-block-tray --group-by colour");
  EXPECT_EQ(group.rc, 2);
  EXPECT_NE(group.err.find("grouping key"), std::string::npos) << group.err;
  const auto algo = ct::run("batch 3-block-tray --algo bfs");
  EXPECT_EQ(algo.rc, 2);
}

}  // namespace
