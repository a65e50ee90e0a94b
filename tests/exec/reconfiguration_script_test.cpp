// Algorithm 2's edit script: the paper's cases and a brute-force property check.
#include "rtamp/exec/reconfiguration_script.hpp"

#include <gtest/gtest.h>

#include <random>

namespace rtamp::exec {
namespace {

using Seq = std::vector<std::string>;
using K = Edit::Kind;

std::size_t count(const std::vector<Edit>& s, K k) {
  std::size_t n = 0;
  for (const Edit& e : s) n += e.kind == k;
  return n;
}

TEST(ReconfigurationScript, IdenticalPlanOnlyUpdatesConditions) {
  Seq old{"move o1 r2", "move o2 r2", "move o3 r2"};
  auto s = reconfiguration_script(old, old);
  EXPECT_EQ(s.size(), 3u);
  EXPECT_EQ(count(s, K::Update), 3u);
  EXPECT_EQ(structural_changes(s), 0u);
}

TEST(ReconfigurationScript, SharedSuffixIsKeptAndFinishedPrefixRemoved) {
  // The first action has been executed; the new plan is the remaining suffix.
  Seq old{"move o1 r2", "move o2 r2", "move o3 r2"};
  Seq plan{"move o2 r2", "move o3 r2"};
  auto s = reconfiguration_script(old, plan);
  EXPECT_EQ(apply_script(old, plan, s), plan);
  EXPECT_EQ(count(s, K::Update), 2u);
  EXPECT_EQ(count(s, K::Remove), 1u);
  EXPECT_EQ(count(s, K::Insert), 0u);
}

TEST(ReconfigurationScript, ActionAddedInTheMiddleIsOneInsert) {
  Seq old{"move o1 r2", "move o3 r2"};
  Seq plan{"move o1 r2", "move o4 r2", "move o3 r2"};
  auto s = reconfiguration_script(old, plan);
  EXPECT_EQ(apply_script(old, plan, s), plan);
  EXPECT_EQ(count(s, K::Insert), 1u);
  EXPECT_EQ(structural_changes(s), 1u);
}

TEST(ReconfigurationScript, ObsoleteActionInTheMiddleIsOneRemove) {
  Seq old{"move o1 r2", "move o2 r2", "move o3 r2"};
  Seq plan{"move o1 r2", "move o3 r2"};
  auto s = reconfiguration_script(old, plan);
  EXPECT_EQ(apply_script(old, plan, s), plan);
  EXPECT_EQ(count(s, K::Remove), 1u);
  EXPECT_EQ(structural_changes(s), 1u);
}

TEST(ReconfigurationScript, EmptyCases) {
  Seq old{"a", "b"};
  EXPECT_EQ(apply_script(old, {}, reconfiguration_script(old, {})), Seq{});
  Seq plan{"x", "y"};
  auto s = reconfiguration_script({}, plan);
  EXPECT_EQ(apply_script({}, plan, s), plan);
  EXPECT_EQ(count(s, K::Insert), 2u);
}

// Brute force: on random small sequences the script always produces the plan,
// every Update/Insert takes the plan tuple at the matching position, and the
// script is never larger than a rebuild from scratch (|old| removes + |new| inserts).
TEST(ReconfigurationScript, RandomSequencesProduceThePlan) {
  std::mt19937 rng(7);
  const Seq alphabet{"a", "b", "c", "d"};
  for (int trial = 0; trial < 5000; ++trial) {
    Seq old, plan;
    for (int k = std::uniform_int_distribution<int>(0, 6)(rng); k > 0; --k) old.push_back(alphabet[rng() % 4]);
    for (int k = std::uniform_int_distribution<int>(0, 6)(rng); k > 0; --k) plan.push_back(alphabet[rng() % 4]);
    auto s = reconfiguration_script(old, plan);
    ASSERT_EQ(apply_script(old, plan, s), plan);
    ASSERT_LE(structural_changes(s), old.size() + plan.size());
    // Replay and check each Update/Insert lands where its plan tuple belongs at the end.
    std::vector<long> origin;  // plan index each position will hold, -1 for old ones
    origin.assign(old.size(), -1);
    for (const Edit& e : s) {
      if (e.kind == K::Remove) origin.erase(origin.begin() + static_cast<long>(e.position));
      else if (e.kind == K::Insert) origin.insert(origin.begin() + static_cast<long>(e.position), static_cast<long>(e.plan_index));
      else origin.at(e.position) = static_cast<long>(e.plan_index);
    }
    for (std::size_t i = 0; i < plan.size(); ++i) ASSERT_EQ(origin[i], static_cast<long>(i));
  }
}

}  // namespace
}  // namespace rtamp::exec
