// batch::resume (batch/resume.hpp), the rows an interrupted batch's CSV keeps:
// whole rows kept and their trials taken off the list, a torn last line
// dropped (whole_bytes ends at the last line end), an empty file or a torn
// header is a batch that had not started; a row of another scenario, another
// seed, another grid, or a row twice is refused at its line.
#include "rtamp/batch/resume.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "rtamp/batch/csv.hpp"
#include "rtamp/util/error.hpp"

namespace {

using namespace rtamp::batch;

std::vector<Trial> grid(std::uint64_t seed = 1) {
  Grid g;
  g.algorithms = {rtamp::plan::Algorithm::AStar};
  g.changes = {ChangeKind::Relocate, ChangeKind::Add};
  g.bt_variants = {BtVariant::OnlineAction};
  g.trials = 3;
  g.base_seed = seed;
  return make_trials(g);
}

EpisodeRecord row(const Trial& t, const std::string& scenario = "3-block") {
  EpisodeRecord r;
  r.scenario = scenario;
  r.algorithm = rtamp::plan::to_string(t.algorithm);
  r.bt = to_string(t.bt);
  r.change = to_string(t.change);
  r.trial = t.index;
  r.seed = t.seed;
  r.success = true;
  r.reason = "task done, \"quoted\"";  // quoted in the CSV
  r.completion_s = 12.5;
  return r;
}

std::string csv(const std::vector<EpisodeRecord>& rs) {
  std::ostringstream o;
  write_csv(o, rs);
  return o.str();
}

std::string what(const std::string& text, const std::vector<Trial>& trials) {
  try {
    resume(text, "r.csv", "3-block", trials);
  } catch (const rtamp::Error& e) {
    return e.what();
  }
  return "";
}

TEST(Resume, KeepsWholeRowsAndListsTheMissingTrials) {
  const auto trials = grid();
  ASSERT_EQ(trials.size(), 6u);
  const std::string text = csv({row(trials[4]), row(trials[1])});
  const Resumed r = resume(text + "3-block,astar,online-act", "r.csv", "3-block", trials);
  EXPECT_EQ(r.whole_bytes, text.size());  // the torn line is dropped
  EXPECT_TRUE(r.has_header);
  ASSERT_EQ(r.kept.size(), 2u);
  EXPECT_EQ(r.kept[0], row(trials[4]));
  ASSERT_EQ(r.missing.size(), 4u);
  for (const Trial& t : r.missing) EXPECT_TRUE(t.index != trials[4].index || t.change != trials[4].change);
  EXPECT_EQ(r.missing[0].index, trials[0].index);
}

TEST(Resume, AnEmptyFileOrATornHeaderHasNotStarted) {
  const auto trials = grid();
  for (const std::string& text : {std::string(), std::string("scenario,algo"), std::string("\n")}) {
    const Resumed r = resume(text, "r.csv", "3-block", trials);
    EXPECT_EQ(r.whole_bytes, 0u);
    EXPECT_FALSE(r.has_header);
    EXPECT_TRUE(r.kept.empty());
    EXPECT_EQ(r.missing.size(), trials.size());
  }
  const Resumed header_only = resume(csv({}), "r.csv", "3-block", trials);
  EXPECT_TRUE(header_only.has_header);
  EXPECT_EQ(header_only.missing.size(), trials.size());
}

TEST(Resume, RefusesRowsOfAnotherBatchAtTheirLine) {
  const auto trials = grid();
  EXPECT_NE(what(csv({row(trials[0]), row(grid(2)[1])}), trials).find("r.csv:3:"), std::string::npos);
  EXPECT_NE(what(csv({row(grid(2)[1])}), trials).find("(another --seed)"), std::string::npos);
  EXPECT_NE(what(csv({row(trials[0], "3-block-tray")}), trials).find("a row of scenario '3-block-tray'"),
            std::string::npos);
  EXPECT_NE(what(csv({row(trials[2]), row(trials[2])}), trials).find("r.csv:3: --resume: the row"),
            std::string::npos);
  EXPECT_NE(what(csv({row(trials[2]), row(trials[2])}), trials).find("is there twice"), std::string::npos);
  Trial other = trials[0];
  other.algorithm = rtamp::plan::Algorithm::Dijkstra;
  EXPECT_NE(what(csv({row(other)}), trials).find("is not a trial of this batch"), std::string::npos);
  EXPECT_NE(what("not,the,header\n", trials).find("r.csv:1:"), std::string::npos);
}

}  // namespace
