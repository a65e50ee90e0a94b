// The Table I summary on synthetic records: grouping, the statistics in each
// cell (completion over successes only), number formatting, and the text,
// Markdown, JSON and TSV renderings; plus the progress line.
#include "rtamp/batch/summary.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

#include "rtamp/batch/progress.hpp"
#include "rtamp/util/error.hpp"

namespace {

using namespace rtamp::batch;

EpisodeRecord rec(const std::string& change, const std::string& algo, const std::string& bt, int trial,
                  double completion, bool success = true) {
  EpisodeRecord r;
  r.scenario = "3-block-tray";
  r.change = change;
  r.algorithm = algo;
  r.bt = bt;
  r.trial = trial;
  r.success = success;
  r.first_plan_s = 0.01 * trial;
  r.replan_s = 0.5 * trial;
  r.replans = trial - 1;
  r.tree_changes = static_cast<std::uint64_t>(2 * trial);
  r.completion_s = completion;
  return r;
}

std::vector<EpisodeRecord> table_one() {
  std::vector<EpisodeRecord> v;
  // Inserted out of canonical order on purpose.
  for (int t = 1; t <= 4; ++t) v.push_back(rec("add", "dijkstra", "online-action", t, 700 + t));
  for (int t = 1; t <= 4; ++t) v.push_back(rec("relocate", "astar", "online-action", t, 500 + 10 * t));
  for (int t = 1; t <= 4; ++t) v.push_back(rec("relocate", "astar-exp", "online-action", t, 400 + t, t != 4));
  return v;
}

TEST(Summary, GroupsInCanonicalOrderWithCellStatistics) {
  const Summary s = summarize(table_one());
  ASSERT_EQ(s.rows.size(), 3u);
  EXPECT_EQ(s.episodes, 12u);
  EXPECT_EQ(s.rows[0].change, "relocate");
  EXPECT_EQ(s.rows[0].algorithm, "astar-exp");
  EXPECT_EQ(s.rows[1].algorithm, "astar");
  EXPECT_EQ(s.rows[2].change, "add");
  const SummaryRow& r = s.rows[0];
  EXPECT_EQ(r.trials, 4u);
  EXPECT_EQ(r.successes, 3u);
  // Completion over the 3 successes: 401, 402, 403 → mean 402, s = 1, CI = 4.3027/sqrt 3.
  EXPECT_EQ(r.completion_s.n, 3u);
  EXPECT_DOUBLE_EQ(r.completion_s.mean, 402);
  EXPECT_NEAR(r.completion_s.ci95, 4.3027 / std::sqrt(3.0), 1e-12);
  // Other metrics over all 4: replans 0,1,2,3 → mean 1.5, median 1.5.
  EXPECT_EQ(r.replans.n, 4u);
  EXPECT_DOUBLE_EQ(r.replans.mean, 1.5);
  EXPECT_DOUBLE_EQ(r.replans.median, 1.5);
  EXPECT_DOUBLE_EQ(r.tree_changes.mean, 5);
}

TEST(Summary, PooledGrouping) {
  auto v = table_one();
  v.push_back(rec("relocate", "astar-exp", "offline", 1, 900));
  const Summary s = summarize(v, parse_grouping("bt"));
  ASSERT_EQ(s.rows.size(), 2u);
  EXPECT_EQ(s.rows[0].bt, "online-action");
  EXPECT_EQ(s.rows[0].trials, 12u);
  EXPECT_EQ(s.rows[0].change, "*");
  EXPECT_EQ(s.rows[1].bt, "offline");
  EXPECT_EQ(s.rows[1].trials, 1u);
  EXPECT_THROW(parse_grouping("bt,colour"), rtamp::Error);
  EXPECT_THROW(parse_grouping(""), rtamp::Error);
  const Grouping g = parse_grouping("scenario,algorithm");
  EXPECT_TRUE(g.scenario && g.algorithm && !g.bt && !g.change);
}

TEST(Summary, NumberFormatting) {
  Stats s;
  s.n = 30;
  s.mean = 466.5;
  s.ci95 = 34.8;
  EXPECT_EQ(mean_ci(s), "466.50 ± 34.80");
  s.mean = 0.0053214;
  s.ci95 = 0.00041;
  EXPECT_EQ(mean_ci(s), "0.00532 ± 0.00041");
  s.ci95 = 0;
  EXPECT_EQ(mean_ci(s), "0.0053 ± 0.0000");
  s.ci95 = NAN;
  EXPECT_EQ(mean_ci(s), "0.0053");
  s.n = 0;
  EXPECT_EQ(mean_ci(s), "—");
  Stats r;
  r.n = 30;
  r.mean = 0.8;
  r.median = 0;
  EXPECT_EQ(mean_median(r), "0.80, 0");
  r.median = 1.5;
  EXPECT_EQ(mean_median(r), "0.80, 1.5");
}

TEST(Summary, TextTable) {
  const std::string t = format_text(summarize(table_one()));
  std::istringstream in(t);
  std::string title, header, rule, row1;
  std::getline(in, title);
  std::getline(in, header);
  std::getline(in, rule);
  std::getline(in, row1);
  // Single-valued keys go to the title, the others are columns.
  EXPECT_EQ(title, "3-block-tray, online-action");
  EXPECT_EQ(header.find("Change"), 0u);
  EXPECT_NE(header.find("Algorithm"), std::string::npos);
  EXPECT_EQ(header.find("BT"), std::string::npos);
  EXPECT_NE(header.find("Completion time (s)"), std::string::npos);
  EXPECT_EQ(row1.rfind("relocate  astar-exp", 0), 0u) << row1;
  EXPECT_NE(row1.find("3/4"), std::string::npos);
  EXPECT_NE(row1.find("1.50, 1.5"), std::string::npos);
  EXPECT_NE(row1.find("402.00 ± 2.48"), std::string::npos) << row1;  // 4.3027/sqrt(3) = 2.484
  // Columns line up: every table line has the same display width up to its last column.
  EXPECT_NE(t.find("12 episodes"), std::string::npos);
  // A rule separates change kinds.
  std::string line;
  int rules = 0;
  while (std::getline(in, line))
    if (line.rfind("─", 0) == 0) ++rules;
  EXPECT_EQ(rules, 1);
}

TEST(Summary, MarkdownTable) {
  const std::string md = format_markdown(summarize(table_one()));
  EXPECT_NE(md.find("**3-block-tray, online-action**"), std::string::npos);
  EXPECT_NE(md.find("| Change | Algorithm | Success | Init plan time (s) | Total replan time (s) | "
                    "# replan (mean, median) | Tree changes | Completion time (s) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| --- | --- | ---: |"), std::string::npos);
  EXPECT_NE(md.find("| relocate | astar-exp | 3/4 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| add | dijkstra | 4/4 |"), std::string::npos) << md;
}

TEST(Summary, JsonAndTsv) {
  const nlohmann::json j = nlohmann::json::parse(to_json(summarize(table_one())));
  EXPECT_EQ(j["episodes"], 12);
  ASSERT_EQ(j["rows"].size(), 3u);
  EXPECT_EQ(j["rows"][0]["algorithm"], "astar-exp");
  EXPECT_EQ(j["rows"][0]["successes"], 3);
  EXPECT_DOUBLE_EQ(j["rows"][0]["completion_s"]["mean"].get<double>(), 402);
  EXPECT_EQ(j["rows"][0]["completion_s"]["n"], 3);
  // A single successful episode: CI is null in JSON.
  const nlohmann::json one = nlohmann::json::parse(to_json(summarize({rec("none", "astar", "offline", 1, 10)})));
  EXPECT_TRUE(one["rows"][0]["completion_s"]["ci95"].is_null());

  const std::string tsv = format_tsv(summarize(table_one()));
  std::istringstream in(tsv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header.rfind("# scenario\tchange\talgorithm\tbt\ttrials\tsuccesses\tfirst_plan_s_mean", 0), 0u);
  EXPECT_EQ(row.rfind("3-block-tray\trelocate\tastar-exp\tonline-action\t4\t3\t", 0), 0u) << row;
  auto count_tabs = [](const std::string& s) { return std::count(s.begin(), s.end(), '\t'); };
  EXPECT_EQ(count_tabs(header), count_tabs(row));
}

TEST(Progress, Formatting) {
  EXPECT_EQ(format_duration(0.25), "0.2s");
  EXPECT_EQ(format_duration(42.9), "42s");
  EXPECT_EQ(format_duration(62), "1m02s");
  EXPECT_EQ(format_duration(7380), "2h03m");
  Progress p{0, 10, 0, 5};
  EXPECT_LT(eta_seconds(p), 0);
  EXPECT_NE(progress_bar(p, 10).find("ETA ?"), std::string::npos);
  p = {4, 10, 1, 40};
  EXPECT_DOUBLE_EQ(eta_seconds(p), 60);
  EXPECT_EQ(progress_bar(p, 10), "[####......] 4/10  elapsed 40s  ETA 1m00s  failures 1");
  p = {10, 10, 0, 100};
  EXPECT_EQ(progress_bar(p, 4), "[####] 10/10  elapsed 1m40s  ETA 0.0s  failures 0");
}

}  // namespace
