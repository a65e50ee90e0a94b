// The planner's hot path allocates nothing per expanded node: counts global
// operator new calls during whole searches (the product graph, the search
// arrays and the motion-cost cache grow geometrically, so their allocations
// grow with the logarithm of the node count, not with it). This executable
// replaces global operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "rtamp/plan/planner.hpp"
#include "rtamp/world/generator.hpp"

#include "../support/counting_new.hpp"

namespace rtamp::plan {
namespace {

world::Scenario layout(int objects, std::uint64_t seed) {
  world::GeneratorOptions g;
  g.regions = 5;
  g.objects = objects;
  g.layout = world::GeneratorOptions::Layout::Random;
  g.seed = seed;
  return world::generate_scenario(g);
}

struct Count {
  long allocations;
  PlanResult result;
};

Count count_plan(Planner& p) {
  const long before = rtamp_allocations();
  PlanResult r = p.plan();
  return {rtamp_allocations() - before, std::move(r)};
}

// The paper's state space (no symmetry reduction): tens of thousands of nodes.
TEST(PlannerAllocations, GrowLogarithmicallyWithTheNodesOfAColdSearch) {
  for (Algorithm a : {Algorithm::Dijkstra, Algorithm::AStar, Algorithm::AStarExperience}) {
    long first_allocations = 0;
    double first_nodes = 0;
    for (int n : {4, 5, 6}) {
      PlannerOptions o;
      o.algorithm = a;
      o.symmetry = false;
      Planner p(layout(n, 3), o);
      const Count c = count_plan(p);
      ASSERT_TRUE(c.result.found);
      const double nodes = double(c.result.stats.generated + c.result.stats.expanded);
      // Plan output (steps, message) and a few dozen geometric growths per array.
      const double budget = 40 * std::log2(nodes + 2) + 4 * double(c.result.plan.prefix.size() + 1) + 100;
      EXPECT_LT(double(c.allocations), budget)
          << to_string(a) << " n=" << n << ": " << c.allocations << " allocations for "
          << c.result.stats.generated << " generated / " << c.result.stats.expanded << " expanded nodes";
      if (n == 4) {
        first_allocations = c.allocations;
        first_nodes = nodes;
      }
      if (n == 6 && a == Algorithm::Dijkstra) {
        // ~30x the nodes of n = 4: the extra allocations are a tiny fraction of the extra nodes.
        EXPECT_GT(c.result.stats.expanded, 10000u) << "the search should be large enough to tell";
        EXPECT_LT(double(c.allocations - first_allocations), 0.01 * (nodes - first_nodes));
      }
      std::printf("%-10s n=%d: %ld allocations, %llu generated, %llu expanded\n", to_string(a), n, c.allocations,
                  static_cast<unsigned long long>(c.result.stats.generated),
                  static_cast<unsigned long long>(c.result.stats.expanded));
    }
  }
}

// A replan after a relocation reuses the graph: no growth, few allocations.
TEST(PlannerAllocations, ReplanAfterARelocationAllocatesAlmostNothing) {
  PlannerOptions o;
  o.symmetry = false;
  Planner p(layout(6, 5), o);
  ASSERT_TRUE(p.plan().found);
  p.apply(world::Change::relocate("o1", "r3"));
  (void)p.plan();  // warm the new region of the graph
  p.apply(world::Change::relocate("o1", "r1"));
  const Count c = count_plan(p);
  ASSERT_TRUE(c.result.found);
  EXPECT_LT(c.allocations, 200) << c.result.stats.expanded << " expanded";
}

}  // namespace
}  // namespace rtamp::plan
