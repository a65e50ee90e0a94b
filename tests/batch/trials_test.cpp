// The trial grid: pairing of seeds, grid size and order, and the shard
// partition property (every trial in exactly one shard, balanced sizes).
#include "rtamp/batch/trials.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "rtamp/util/error.hpp"

namespace {

using namespace rtamp::batch;

Grid full_grid(int trials) {
  Grid g;
  g.algorithms = {rtamp::plan::Algorithm::AStarExperience, rtamp::plan::Algorithm::AStar, rtamp::plan::Algorithm::Dijkstra};
  g.changes = {ChangeKind::Relocate, ChangeKind::Add, ChangeKind::Remove, ChangeKind::None};
  g.bt_variants = {BtVariant::OnlineAction, BtVariant::OnlineState, BtVariant::Offline};
  g.trials = trials;
  g.base_seed = 7;
  return g;
}

auto key(const Trial& t) { return std::make_tuple(int(t.algorithm), int(t.change), int(t.bt), t.index); }

TEST(Trials, GridIsComplete) {
  const auto trials = make_trials(full_grid(5));
  EXPECT_EQ(trials.size(), 3u * 4u * 3u * 5u);
  std::set<std::tuple<int, int, int, int>> keys;
  for (const auto& t : trials) keys.insert(key(t));
  EXPECT_EQ(keys.size(), trials.size());
  // Trial-major: every cell's trial 1 before any trial 2.
  for (std::size_t i = 0; i + 1 < trials.size(); ++i) EXPECT_LE(trials[i].index, trials[i + 1].index);
}

TEST(Trials, SeedsArePairedAcrossAlgorithmsAndVariants) {
  const auto trials = make_trials(full_grid(20));
  std::map<int, std::uint64_t> seed_of;
  for (const auto& t : trials) {
    auto [it, fresh] = seed_of.emplace(t.index, t.seed);
    EXPECT_EQ(it->second, t.seed) << "trial " << t.index;
    EXPECT_EQ(t.seed, trial_seed(t.index, 7));
  }
  std::set<std::uint64_t> distinct;
  for (auto& [i, s] : seed_of) distinct.insert(s);
  EXPECT_EQ(distinct.size(), seed_of.size()) << "different trials must get different seeds";
  // The base seed changes every trial's seed.
  for (int i = 1; i <= 20; ++i) EXPECT_NE(trial_seed(i, 7), trial_seed(i, 8));
  // Deterministic.
  EXPECT_EQ(make_trials(full_grid(20)).at(17).seed, trials.at(17).seed);
}

TEST(Trials, DuplicatesDroppedAndEmptyRejected) {
  Grid g = full_grid(2);
  g.algorithms = {rtamp::plan::Algorithm::AStar, rtamp::plan::Algorithm::AStar};
  EXPECT_EQ(make_trials(g).size(), 1u * 4u * 3u * 2u);
  g.changes.clear();
  EXPECT_THROW(make_trials(g), rtamp::Error);
  g = full_grid(0);
  EXPECT_THROW(make_trials(g), rtamp::Error);
}

TEST(Trials, NamesRoundTrip) {
  for (auto c : {ChangeKind::Relocate, ChangeKind::Remove, ChangeKind::Add, ChangeKind::None}) EXPECT_EQ(parse_change_kind(to_string(c)), c);
  for (auto b : {BtVariant::OnlineAction, BtVariant::OnlineState, BtVariant::Offline})
    EXPECT_EQ(parse_bt_variant(to_string(b)), b);
  EXPECT_THROW(parse_change_kind("move"), rtamp::Error);
  EXPECT_THROW(parse_bt_variant("online"), rtamp::Error);
  EXPECT_LT(change_rank("relocate"), change_rank("remove"));
  EXPECT_LT(change_rank("remove"), change_rank("add"));
  // Algorithms rank in the registry's order (Table I: astar-exp, astar, dijkstra).
  EXPECT_LT(algorithm_rank("astar-exp"), algorithm_rank("astar"));
  EXPECT_LT(algorithm_rank("astar"), algorithm_rank("dijkstra"));
  EXPECT_GT(algorithm_rank("bfs"), algorithm_rank("dijkstra"));
  EXPECT_GT(bt_rank("unknown"), bt_rank("offline"));
}

TEST(Shards, ParseAcceptsAndRejects) {
  const Shard s = parse_shard("3/8");
  EXPECT_EQ(s.k, 3);
  EXPECT_EQ(s.n, 8);
  EXPECT_EQ(parse_shard("1/1").n, 1);
  for (const char* bad : {"0/4", "5/4", "4", "/4", "1/", "a/b", "1/0", "-1/4", "1/4x", " 1/4", "1//4", ""})
    EXPECT_THROW(parse_shard(bad), rtamp::Error) << bad;
}

TEST(Shards, PartitionEveryTrialExactlyOnce) {
  for (int trials : {1, 2, 7, 30}) {
    const auto all = make_trials(full_grid(trials));
    for (int n = 1; n <= 13; ++n) {
      std::map<std::tuple<int, int, int, int>, int> count;
      std::size_t min_size = all.size(), max_size = 0;
      for (int k = 1; k <= n; ++k) {
        const auto slice = select_shard(all, Shard{k, n});
        min_size = std::min(min_size, slice.size());
        max_size = std::max(max_size, slice.size());
        for (const auto& t : slice) ++count[key(t)];
        // A slice keeps the list's order.
        for (std::size_t i = 0; i + 1 < slice.size(); ++i) EXPECT_LE(slice[i].index, slice[i + 1].index);
      }
      EXPECT_EQ(count.size(), all.size()) << trials << " trials, " << n << " shards";
      for (auto& [k, c] : count) EXPECT_EQ(c, 1);
      EXPECT_LE(max_size - min_size, 1u);
    }
  }
}

TEST(Shards, SliceTrialsKeepTheirSeeds) {
  const auto all = make_trials(full_grid(6));
  for (const auto& t : select_shard(all, Shard{2, 5})) EXPECT_EQ(t.seed, trial_seed(t.index, 7));
}

}  // namespace
