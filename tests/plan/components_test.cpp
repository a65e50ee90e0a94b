// Pieces of the plan layer: the motion-cost models' documented formulas, the
// experience cache (hits, misses, forgetting), the guard heuristic's
// admissibility against the brute force from random states.
#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/plan/motion_cost_cache.hpp"
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

plan::PlannerOptions with_cost(const char* model) {
  plan::PlannerOptions o;
  o.cost = model;
  return o;
}

// A planner for `sc` with cost model `model` in a random state
// (place_randomly), its product graph and its heuristic.
struct RandomStart {
  RandomStart(const world::Scenario& sc, const char* model, std::mt19937& rng)
      : p(sc, with_cost(model)),
        placed(place_randomly(rng, p)),
        s(p.state()),
        cost(plan::make_cost_model(model)),
        g(p.system(), p.labeling(), p.automaton(), *cost, nullptr),
        h(g) {}
  plan::Planner p;
  std::pair<world::Placement, std::string> placed;
  task::State s;
  std::shared_ptr<plan::MotionCostModel> cost;
  plan::ProductGraph g;
  plan::GuardHeuristic h;
};

// The join's stretch (ChainBound::join_bound) is the binding part of h on
// recurrent tasks, which the pattern set above seldom draws: h(s, q) <= the
// best lasso from (s, q) on random patrols (conjunctions of G F, with and
// without F G and F parts), every model, random states and hands.
TEST(GuardHeuristic, JoinBoundAdmissibleOnPatrols) {
  const std::vector<std::string> formulas = {"G F a & G F b", "G F a & G F b & G F c",
                                             "G F a & G F b & F G c", "F a & G F b & G F c",
                                             "G F (a & b) & G F c"};
  std::mt19937 rng(24);
  int checked = 0, tight = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    if (!sc.containers.empty()) continue;  // no chain bound with containers
    for (const char* model : {"euclid", "region", "unit"}) {
      RandomStart r(sc, model, rng);
      for (std::uint32_t q = 0; q < r.p.automaton().num_states(); ++q) {
        if (!r.g.useful(q)) continue;
        automata::Automaton ba = r.p.automaton();
        ba.initial = q;
        const auto lasso = oracle::min_lasso(r.p.scenario(), r.placed.first, r.placed.second, ba, model);
        if (!lasso) continue;
        const double est = r.h.evaluate(r.s, q);
        EXPECT_LE(est, *lasso + 1e-9) << sc.task << " q=" << q << " model " << model;
        ++checked;
        tight += est > 0 && est >= *lasso - 1e-9;
      }
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(tight, 30);  // the bound is often exact here
}

// Admissibility against the brute-force product, from random states, for
// every model: h(s, q) <= the best lasso from (s, q); the walk bounds (the
// automaton part of h, and what the cycle search uses) <= exact distances:
// walk(s, q, any accepting) <= the cheapest path to a node with a useful
// accepting BA state, walk(s, q, t) <= the cheapest path of at least one step
// to a node with BA state t.
TEST(GuardHeuristic, AdmissibleAgainstBruteForce) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(11);
  int checked = 0, positive = 0, cycle_positive = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    for (const char* model : {"euclid", "region", "unit"}) {
      RandomStart r(sc, model, rng);
      plan::Planner& p = r.p;
      const auto& [pl, hand] = r.placed;
      const task::State& s = r.s;
      plan::ProductGraph& g = r.g;
      plan::GuardHeuristic& h = r.h;
      const std::uint32_t nq = p.automaton().num_states();
      for (std::uint32_t q = 0; q < nq; ++q) {
        if (!g.useful(q)) continue;
        automata::Automaton ba = p.automaton();
        ba.initial = q;
        const oracle::Product prod(p.scenario(), pl, hand, ba, model);
        const auto d0 = prod.dijkstra(0, false);
        const auto d1 = prod.dijkstra(0, true);
        double to_acc = INFINITY;
        std::vector<double> to_q(nq, INFINITY);
        for (std::size_t n = 0; n < prod.nodes.size(); ++n) {
          const std::uint32_t qn = prod.nodes[n].q;
          if (ba.is_accepting_state(qn) && g.useful(qn)) to_acc = std::min(to_acc, d0[n]);
          to_q[qn] = std::min(to_q[qn], d1[n]);
        }
        // h bounds the best lasso (prefix and cycle); the walk part alone bounds
        // the distance to acceptance.
        const double est = h.evaluate(s, q);
        const auto lasso = oracle::min_lasso(p.scenario(), pl, hand, ba, model);
        if (lasso) {
          EXPECT_LE(est, *lasso + 1e-9) << sc.task << " q=" << q << " model " << model;
          ++checked;
          positive += est > 0;
        }
        if (to_acc < INFINITY && !ba.is_accepting_state(q)) {
          const double w = h.walk(s, q, plan::GuardHeuristic::kAnyAccepting);
          EXPECT_LE(w, to_acc + 1e-9) << sc.task << " q=" << q << " model " << model;
          ++checked;
        }
        // cycle_bound <= the cheapest cycle through the start node that
        // passes an accepting node (the cycle of a lasso joined there):
        // min over accepting N of d(start, N) + d(N, start).
        {
          std::vector<std::size_t> acc;
          for (std::size_t n = 0; n < prod.nodes.size(); ++n)
            if (ba.is_accepting_state(prod.nodes[n].q) && d0[n] < INFINITY) acc.push_back(n);
          std::sort(acc.begin(), acc.end(), [&](std::size_t a, std::size_t b) { return d0[a] < d0[b]; });
          double u = INFINITY;
          for (std::size_t n : acc) {
            if (d0[n] >= u) break;
            u = std::min(u, n == 0 ? d1[0] : d0[n] + prod.dijkstra(static_cast<int>(n), false)[0]);
          }
          expect_cycle_bound(h, g, s, q, u, sc.task + " model " + model, checked, cycle_positive);
        }
        for (std::uint32_t t = 0; t < nq; ++t) {
          if (!g.useful(t) || to_q[t] == INFINITY) continue;
          const double w = h.walk(s, q, t);
          EXPECT_LE(w, to_q[t] + 1e-9) << sc.task << " q=" << q << " -> " << t << " model " << model;
          ++checked;
          positive += w > 0;
        }
      }
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(positive, 100);  // the bounds are not trivially 0
  EXPECT_GT(cycle_positive, 5);
}

}  // namespace
