// plan/experience.hpp (A* with experience, one home) and world::Change as the
// one change type: the per-node tables read "unknown" until written, learn()
// only raises a bound, a solved node keeps its exact value and first edge, a
// cycle's edges are recorded once, forget_graph() drops every per-node table
// but keeps the motion-cost cache; a planner's replans after a relocation keep
// its experience and after an addition start a new graph; a scripted
// intervention (world::Intervention) is applied by the planner exactly like
// the same change written as text, and a change the planner cannot represent
// (take-from-gripper) is refused.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/change.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

TEST(Experience, TablesAndForgetting) {
  plan::Experience x;
  EXPECT_EQ(x.learned(7), 0.0);
  EXPECT_FALSE(x.solved(7));
  EXPECT_EQ(x.cached_h(7), plan::Experience::kUnknownH);
  EXPECT_FALSE(x.cycle(7).exact);
  x.learn(7, 3.0);
  x.learn(7, 2.0);  // a weaker bound does not lower it
  EXPECT_EQ(x.learned(7), 3.0);
  x.set_solved(9, 5.0, 2, 4);
  EXPECT_TRUE(x.solved(9));
  EXPECT_EQ(x.learned(9), 5.0);
  EXPECT_EQ(x.via(9), 4u);
  EXPECT_EQ(x.solved_moves(9), 2u);
  EXPECT_FALSE(x.solved(8));  // a neighbour grown with the table is not solved
  x.set_cycle(3, {1.5, 2, true});
  x.set_cycle_path(3, {10, 11});
  x.set_cycle_path(3, {12});  // recorded once
  std::vector<std::uint32_t> path;
  ASSERT_TRUE(x.cycle_path(3, path));
  EXPECT_EQ(path, (std::vector<std::uint32_t>{10, 11}));
  EXPECT_FALSE(x.cycle_path(2, path));
  x.cache_h(1000, 0.25);
  EXPECT_EQ(x.cached_h(1000), 0.25);
  EXPECT_EQ(x.cached_h(999), plan::Experience::kUnknownH);

  plan::EuclidCost e;
  plan::MotionQuery q;
  q.to = {1, 0, 0};
  (void)x.costs().lookup(q, e);
  EXPECT_GT(x.memory_bytes(), 0u);
  x.forget_graph();
  EXPECT_EQ(x.learned(7), 0.0);
  EXPECT_FALSE(x.solved(9));
  EXPECT_FALSE(x.cycle(3).exact);
  EXPECT_FALSE(x.cycle_path(3, path));
  EXPECT_EQ(x.cached_h(1000), plan::Experience::kUnknownH);
  EXPECT_EQ(x.memory_bytes(), 0u);   // released with the graph
  EXPECT_EQ(x.costs().size(), 1u);  // the cost cache outlives the graph
}

TEST(Experience, KeptAcrossRelocationsDroppedWithTheGraph) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  ASSERT_TRUE(p.plan().found);
  const std::size_t learned = p.experience().memory_bytes();
  EXPECT_GT(learned, 0u);  // the first search recorded cycles and solved paths
  p.apply(world::Change::relocate("o1", "r3"));
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  EXPECT_GT(r.stats.reused_nodes, 0u);  // same graph
  p.apply(world::Change::add_object("o9", "block", "r1"));
  const auto r2 = p.plan();
  ASSERT_TRUE(r2.found);
  EXPECT_EQ(r2.stats.reused_nodes, 0u);  // a new TS, a new graph
}

TEST(OneChangeType, InterventionsAreChanges) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  world::Intervention iv;
  iv.time = 12.5;
  iv.kind = world::Change::Kind::Relocate;
  iv.subject = "o2";
  iv.location = "r3";
  EXPECT_EQ(iv.to_string(), "move o2 r3");
  EXPECT_STREQ(world::to_string(iv.kind), "relocate");
  plan::Planner a(s), b(s);
  a.apply(iv);
  b.apply(world::Change::parse("move o2 r3"));
  EXPECT_EQ(a.placement().location_of("o2") ? *a.placement().location_of("o2") : "", "r3");
  const auto ra = a.plan(), rb = b.plan();
  ASSERT_TRUE(ra.found && rb.found);
  EXPECT_DOUBLE_EQ(ra.plan.prefix_cost + ra.plan.cycle_cost, rb.plan.prefix_cost + rb.plan.cycle_cost);
  // The gripper's contents are not part of the planner's state.
  EXPECT_THROW(a.apply(world::Change::take_from_gripper("r1")), Error);
  EXPECT_EQ(world::Change::take_from_gripper("r1").to_string(), "take-from-gripper r1");
  // Every kind has its own name.
  std::set<std::string> names;
  for (auto k : {world::Change::Kind::Relocate, world::Change::Kind::Add, world::Change::Kind::Remove,
                 world::Change::Kind::AddContainer, world::Change::Kind::RemoveContainer,
                 world::Change::Kind::TakeFromGripper, world::Change::Kind::AddRegion})
    EXPECT_TRUE(names.insert(world::to_string(k)).second);
}

}  // namespace
