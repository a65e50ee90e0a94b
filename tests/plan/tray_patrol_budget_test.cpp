// Work bounds of the class patrol with three trays (the state of a real
// episode's replan): four blocks of one class in r1 of `rtamp gen --regions 4
// --objects 4 --containers 3`, task G F all_in_r2 & G F all_in_r3, r2 and r3
// holding 3 (no plan: the capacities forbid it) or 4 (a plan). Counted in
// deterministic work (expansions, nodes), never in time: the trays are one
// symmetry group (task::System::set_container_symmetry) and "no plan" is
// diagnosed by the existence check (plan/lasso_exists.hpp), not by a second
// optimal search. The bounds are the counts measured when they were
// recorded, with a little room; docs/benchmarks.md has the times.
#include <gtest/gtest.h>

#include "rtamp/plan/planner.hpp"
#include "rtamp/world/generator.hpp"

namespace {

using namespace rtamp;

world::Scenario tray_patrol(int capacity) {
  world::GeneratorOptions g;
  g.regions = 4;
  g.objects = 4;
  g.containers = 3;
  g.task = "G F all_in_r2 & G F all_in_r3";
  g.propositions = {{"all_in_r3", "all block in r3"}};
  world::Scenario sc = world::generate_scenario(g);
  sc.regions[1].capacity = capacity;
  sc.regions[2].capacity = capacity;
  return sc;
}

TEST(TrayPatrolBudget, TheTraysAreOneSymmetryGroup) {
  plan::Planner p(tray_patrol(4));
  EXPECT_TRUE(p.system().has_container_symmetry());
  for (unsigned t = p.system().num_objects(); t < p.system().num_things(); ++t)
    EXPECT_EQ(p.system().container_group_of(t), 0);
}

TEST(TrayPatrolBudget, NoPlanWithinCapacityThree) {
  plan::Planner p(tray_patrol(3));
  const auto r = p.plan();
  ASSERT_FALSE(r.found);
  EXPECT_EQ(r.reason, plan::NoPlanReason::Capacity) << r.message;
  EXPECT_LE(r.stats.expanded, kNoPlanExpanded);
  EXPECT_LE(r.stats.graph_nodes, kNoPlanNodes);
  EXPECT_GT(r.stats.diagnosis_nodes, 0u);
  EXPECT_LE(r.stats.diagnosis_nodes, kDiagnosisNodes);
}

TEST(TrayPatrolBudget, PlanWithinCapacityFour) {
  plan::Planner p(tray_patrol(4));
  const auto r = p.plan();
  ASSERT_TRUE(r.found) << r.message;
  EXPECT_NEAR(r.plan.cost(), kPlanCost, 1e-9);
  EXPECT_LE(r.stats.expanded, kPlanExpanded);
  EXPECT_LE(r.stats.graph_nodes, kPlanNodes);
}

}  // namespace
