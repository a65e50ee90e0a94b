// Pieces of the plan layer: the motion-cost models' documented formulas, the
// experience cache (hits, misses, forgetting), the guard heuristic's
// admissibility against the brute force from random states.
#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/motion_cost.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

TEST(MotionCost, DocumentedExample) {
  plan::EuclidCost e;
  plan::MotionQuery q;
  q.hand = {0, 0, 0.5};
  q.from = {0.4, 0, 0};
  q.to = {0.4, 0.5, 0};
  EXPECT_NEAR(e.cost(q), std::sqrt(0.16 + 0.25) + 0.5, 1e-12);
  EXPECT_NEAR(plan::RegionCost().cost(q), 0.5, 1e-12);
  EXPECT_EQ(plan::UnitCost().cost(q), 1.0);
  EXPECT_THROW(plan::make_cost_model("ik9"), Error);
  EXPECT_EQ(plan::make_cost_model("region")->name(), "region");
}

TEST(MotionCostCache, HitsMissesAndForgetting) {
  plan::EuclidCost e;
  plan::MotionCostCache cache(e.depends());
  plan::MotionQuery a;
  a.thing = 1;
  a.hand = {0, 0, 0.5};
  a.from = {1, 0, 0};
  a.to = {2, 0, 0};
  plan::MotionQuery b = a;
  b.thing = 2;  // euclid does not depend on the thing: same entry
  EXPECT_NEAR(cache.lookup(a, e), e.cost(a), 1e-12);
  EXPECT_NEAR(cache.lookup(b, e), e.cost(a), 1e-12);
  EXPECT_EQ(cache.misses(), 1u);
  EXPECT_EQ(cache.hits(), 1u);
  for (int i = 0; i < 5000; ++i) {  // growth keeps entries
    plan::MotionQuery q = a;
    q.to = {double(i), 1, 0};
    EXPECT_NEAR(cache.lookup(q, e), e.cost(q), 1e-12);
  }
  EXPECT_NEAR(cache.lookup(a, e), e.cost(a), 1e-12);
  EXPECT_EQ(cache.hits(), 2u);
  // A model that depends on the thing: forgetting drops only that thing.
  plan::MotionCostCache c2(plan::kDependsAll);
  c2.lookup(a, e);
  c2.lookup(b, e);
  c2.forget_thing(1);
  EXPECT_EQ(c2.size(), 1u);
  c2.reset_counters();
  c2.lookup(b, e);
  c2.lookup(a, e);
  EXPECT_EQ(c2.hits(), 1u);
  EXPECT_EQ(c2.misses(), 1u);
}

// h(start) <= the optimal lasso cost from random reachable states, for every model.
TEST(GuardHeuristic, AdmissibleAgainstBruteForce) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(5);
  int checked = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    for (const char* model : {"euclid", "region", "unit"}) {
      plan::PlannerOptions opt;
      opt.cost = model;
      plan::Planner p(sc, opt);
      // A random state: every thing somewhere legal, hand anywhere.
      world::Placement pl = p.placement();
      std::vector<std::string> regions, locs;
      for (const auto& r : sc.regions) regions.push_back(r.name);
      locs = regions;
      for (const auto& c : sc.containers) locs.push_back(c.name);
      for (auto& [name, thing] : pl.things) thing.location = thing.container ? regions[rng() % regions.size()] : locs[rng() % locs.size()];
      const std::string hand = rng() % 3 ? locs[rng() % locs.size()] : "";
      p.set_placement(pl, hand);
      const task::State s = p.state();
      auto model_ptr = plan::make_cost_model(model);
      plan::ProductGraph g(p.system(), p.labeling(), p.automaton(), *model_ptr, nullptr);
      plan::GuardHeuristic h(g);
      for (std::uint32_t q = 0; q < p.automaton().num_states(); ++q) {
        if (!g.useful(q)) continue;
        automata::Automaton ba = p.automaton();
        ba.initial = q;
        const auto best = oracle::min_lasso(p.scenario(), pl, hand, ba, model);
        const double est = h.evaluate(s, q);
        if (best) {
          EXPECT_LE(est, *best + 1e-9) << sc.task << " q=" << q << " model " << model;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 300);
}

}  // namespace
