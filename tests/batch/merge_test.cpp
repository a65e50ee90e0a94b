// Merging CSV slices of a sharded batch: slices of a grid merge back to the
// whole, in canonical order; duplicates, header mismatches and slices run with
// different seeds are refused.
#include "rtamp/batch/merge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "rtamp/batch/csv.hpp"
#include "rtamp/batch/trials.hpp"
#include "rtamp/util/error.hpp"

namespace {

using namespace rtamp::batch;

EpisodeRecord record_of(const Trial& t) {
  EpisodeRecord r;
  r.scenario = "3-block-tray";
  r.algorithm = to_string(t.algorithm);
  r.bt = to_string(t.bt);
  r.change = to_string(t.change);
  r.trial = t.index;
  r.seed = t.seed;
  r.success = true;
  r.reason = "task done";
  r.completion_s = 100 + t.index;
  return r;
}

std::string csv_of(const std::vector<Trial>& trials) {
  std::vector<EpisodeRecord> rs;
  for (const auto& t : trials) rs.push_back(record_of(t));
  std::ostringstream o;
  write_csv(o, rs);
  return o.str();
}

std::vector<Trial> grid() {
  Grid g;
  g.algorithms = {rtamp::plan::Algorithm::Dijkstra, rtamp::plan::Algorithm::AStarExperience, rtamp::plan::Algorithm::AStar};
  g.changes = {ChangeKind::Add, ChangeKind::Relocate, ChangeKind::Remove};
  g.bt_variants = {BtVariant::OnlineAction};
  g.trials = 4;
  g.base_seed = 11;
  return make_trials(g);
}

std::string error_of(const std::vector<CsvSource>& s) {
  try {
    merge_slices(s);
  } catch (const rtamp::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Merge, ShardsMergeBackToTheWholeSorted) {
  const auto all = grid();
  std::vector<CsvSource> slices;
  for (int k = 3; k >= 1; --k)  // out of order on purpose
    slices.push_back({"slice" + std::to_string(k) + ".csv", csv_of(select_shard(all, Shard{k, 3}))});
  const auto merged = merge_slices(slices);
  ASSERT_EQ(merged.size(), all.size());
  // Same set of rows as the unsharded run...
  std::vector<EpisodeRecord> whole;
  for (const auto& t : all) whole.push_back(record_of(t));
  sort_canonical(whole);
  EXPECT_EQ(merged, whole);
  // ...in the canonical order: relocate < remove < add, astar-exp < astar < dijkstra, then trial.
  EXPECT_TRUE(std::is_sorted(merged.begin(), merged.end(), canonical_less));
  EXPECT_EQ(merged.front().change, "relocate");
  EXPECT_EQ(merged.front().algorithm, "astar-exp");
  EXPECT_EQ(merged.front().trial, 1);
  EXPECT_EQ(merged.back().change, "add");
  EXPECT_EQ(merged.back().algorithm, "dijkstra");
  EXPECT_EQ(merged.back().trial, 4);
}

TEST(Merge, PartialGridIsFine) {
  const auto all = grid();
  const auto merged = merge_slices({{"a.csv", csv_of(select_shard(all, Shard{1, 4}))}});
  EXPECT_EQ(merged.size(), select_shard(all, Shard{1, 4}).size());
}

TEST(Merge, DuplicateRowsRejected) {
  const auto all = grid();
  const std::string a = csv_of(select_shard(all, Shard{1, 2}));
  // The same slice twice.
  const std::string e1 = error_of({{"a.csv", a}, {"b.csv", a}});
  EXPECT_NE(e1.find("duplicate"), std::string::npos) << e1;
  EXPECT_NE(e1.find("a.csv"), std::string::npos) << e1;
  EXPECT_NE(e1.find("b.csv"), std::string::npos) << e1;
  // Overlapping shards (1/2 and 1/4 share trials).
  const std::string e2 = error_of({{"a.csv", a}, {"c.csv", csv_of(select_shard(all, Shard{1, 4}))}});
  EXPECT_NE(e2.find("duplicate"), std::string::npos) << e2;
  // A duplicate inside one file.
  std::vector<Trial> twice = {all[0], all[1], all[0]};
  const std::string e3 = error_of({{"d.csv", csv_of(twice)}});
  EXPECT_NE(e3.find("duplicate"), std::string::npos) << e3;
}

TEST(Merge, HeaderMismatchRejected) {
  const auto all = grid();
  const std::string a = csv_of(select_shard(all, Shard{1, 2}));
  std::string b = csv_of(select_shard(all, Shard{2, 2}));
  b.replace(0, std::string("scenario").size(), "scene");
  const std::string e = error_of({{"a.csv", a}, {"b.csv", b}});
  EXPECT_NE(e.find("header differs"), std::string::npos) << e;
  EXPECT_NE(e.find("b.csv"), std::string::npos) << e;
  // Same (wrong) header in all files: refused by the reader.
  const std::string e2 = error_of({{"b.csv", b}});
  EXPECT_NE(e2.find("header"), std::string::npos) << e2;
}

TEST(Merge, DifferentSeedsRejected) {
  Grid g;
  g.algorithms = {rtamp::plan::Algorithm::AStar};
  g.changes = {ChangeKind::Relocate};
  g.bt_variants = {BtVariant::OnlineAction, BtVariant::Offline};
  g.trials = 2;
  g.base_seed = 1;
  const auto one = make_trials(g);
  g.base_seed = 2;
  const auto two = make_trials(g);
  const std::string e = error_of({{"s1.csv", csv_of(select_shard(one, Shard{1, 2}))},
                                  {"s2.csv", csv_of(select_shard(two, Shard{2, 2}))}});
  EXPECT_NE(e.find("different --seed"), std::string::npos) << e;
}

TEST(Merge, NoInputRejected) { EXPECT_THROW(merge_slices({}), rtamp::Error); }

}  // namespace
