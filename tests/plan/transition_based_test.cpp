// Acceptance on transitions: on random small scenarios (with and without a
// tray) and the task families reach, sequence, split, patrol and reach-avoid,
// the planner searching a transition-based Büchi automaton returns the cost
// of the planner searching the state-based one, and both the cost of the
// independent brute force (oracle.hpp) on the state-based automaton and on
// the transition-based one's state-based form; "no plan" agrees too, and
// every transition-based plan passes check_plan.
#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/automata/degeneralize_tba.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/registry.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

// The families, with atoms that random_scenario binds to random propositions.
const std::vector<std::string> kFamilies = {
    "F a",                              // reach
    "F (a & F b)",                      // sequence
    "F (a & F G b)",                    // sequence, then stay
    "F(a & F(b & F c))",                // sequence of three
    "F G (a & b)",                      // split: two halves held at once
    "G F a & G F b",                    // patrol
    "G F a & G F b & G F c",            // patrol of three
    "G F a & G F b & G !c",             // patrol avoiding
    "F a & G !b",                       // reach-avoid
    "!b U a",                           // reach-avoid until
    "G (a -> F b) & G F c",             // response under recurrence
};

const plan::Algorithm kAlgos[] = {plan::Algorithm::AStar, plan::Algorithm::AStarExperience,
                                  plan::Algorithm::Dijkstra};

TEST(TransitionBased, CostsEqualStateBasedAndBruteForce) {
  std::mt19937 rng(4242);
  const char* models[] = {"euclid", "region", "unit"};
  int found = 0, none = 0, trays = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const world::Scenario sc = random_scenario(rng, kFamilies);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    trays += sc.containers.empty() ? 0 : 1;
    plan::PlannerOptions opt;
    opt.algorithm = plan::Algorithm::AStar;
    opt.cost = model;
    plan::Planner state(sc, opt);
    opt.transition_based = true;
    opt.generalized = plan::PlannerOptions::Generalized::Never;  // one set (generalized: generalized_test.cpp)
    opt.algorithm = kAlgos[trial % 3];
    opt.graph = trial % 2 ? plan::GraphConstruction::Full : plan::GraphConstruction::Partial;
    plan::Planner trans(sc, opt);
    ASSERT_TRUE(state.automaton().state_based);
    ASSERT_FALSE(trans.automaton().state_based);
    ASSERT_EQ(trans.automaton().num_sets, 1u);
    const auto want = oracle::min_lasso(state.scenario(), state.placement(), state.hand(), state.automaton(), model);
    const auto want_tb = oracle::min_lasso(trans.scenario(), trans.placement(), trans.hand(),
                                           automata::state_based_form(trans.automaton()), model);
    ASSERT_EQ(want.has_value(), want_tb.has_value());
    if (want) {
      EXPECT_NEAR(*want, *want_tb, 1e-6);
    }
    const plan::PlanResult rs = state.plan();
    const plan::PlanResult rt = trans.plan();
    ASSERT_EQ(rs.found, want.has_value()) << rs.message;
    ASSERT_EQ(rt.found, want.has_value()) << rt.message;
    if (!want) {
      ++none;
      EXPECT_EQ(rt.reason, rs.reason) << rt.message;
      continue;
    }
    ++found;
    EXPECT_NEAR(rs.plan.cost(), *want, 1e-6);
    EXPECT_NEAR(rt.plan.cost(), *want, 1e-6);
    check_plan(trans, rt, model);
  }
  EXPECT_GT(found, 300);
  EXPECT_GT(none, 3);
  EXPECT_GT(trays, 100);
}

// The heuristic's bounds on a transition-based automaton, from random states
// (hand anywhere or at home) and every useful automaton state q, against the
// brute force on the automaton's state-based form (q keeps its number there,
// as its non-accepting copy): h(s, q) <= the best lasso from (s, q), and
// cycle_bound <= the cheapest cycle through (s, q) that takes an accepting
// edge (one returning to (s, q) or to its accepting copy, whose edges are
// the same). Half the scenarios without a tray are patrols whose atoms force
// every block (where the chain bound's cycle bound is positive).
TEST(TransitionBased, HeuristicAdmissibleAgainstBruteForce) {
  std::mt19937 rng(7);
  int checked = 0, positive = 0, cycle_positive = 0;
  for (int trial = 0; trial < 150; ++trial) {
    world::Scenario sc = random_scenario(rng, kFamilies);
    if (trial % 2 && sc.containers.empty()) make_forcing_patrol(sc, trial % 4 == 1 ? 2 : 3);
    for (const char* model : {"euclid", "region", "unit"}) {
      plan::PlannerOptions opt;
      opt.cost = model;
      opt.transition_based = true;
      opt.generalized = plan::PlannerOptions::Generalized::Never;  // one set (generalized: generalized_test.cpp)
      plan::Planner p(sc, opt);
      const auto [pl, hand] = place_randomly(rng, p);
      const task::State s = p.state();
      const auto cost = plan::make_cost_model(model);
      plan::ProductGraph g(p.system(), p.labeling(), p.automaton(), *cost, nullptr);
      plan::GuardHeuristic h(g);
      const automata::Automaton form = automata::state_based_form(p.automaton());
      for (std::uint32_t q = 0; q < p.automaton().num_states(); ++q) {
        if (!g.useful(q)) continue;
        automata::Automaton ba = form;
        ba.initial = q;
        const auto lasso = oracle::min_lasso(p.scenario(), pl, hand, ba, model);
        if (!lasso) continue;
        const double est = h.evaluate(s, q);
        EXPECT_LE(est, *lasso + 1e-9) << sc.task << " q=" << q << " model " << model;
        ++checked;
        positive += est > 0;
        // q itself, and the accepting copies with q's edges.
        auto is_q = [&](std::uint32_t c) { return c == q || (ba.state_accepting[c] && ba.edges[c] == ba.edges[q]); };
        const oracle::Product prod(p.scenario(), pl, hand, ba, model);
        const auto d0 = prod.dijkstra(0, false);
        double u = INFINITY;
        for (std::size_t n = 0; n < prod.nodes.size(); ++n) {
          if (!ba.is_accepting_state(prod.nodes[n].q) || d0[n] >= u) continue;
          const auto back = prod.dijkstra(static_cast<int>(n), false);
          for (std::size_t m = 0; m < prod.nodes.size(); ++m)
            if (prod.nodes[m].s.loc == prod.nodes[0].s.loc && prod.nodes[m].s.hand == prod.nodes[0].s.hand &&
                is_q(prod.nodes[m].q))
              u = std::min(u, d0[n] + back[m]);
        }
        expect_cycle_bound(h, g, s, q, u, sc.task + " model " + model, checked, cycle_positive);
      }
    }
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(positive, 200);       // the bounds are not trivially 0
  EXPECT_GT(cycle_positive, 30);  // nor the chain bound's cycle bound
}

// Replans on one transition-based planner (experience kept) after the robot
// moved things: each equals a cold state-based plan from the same placement.
TEST(TransitionBased, ReplansEqualStateBased) {
  std::mt19937 rng(99);
  int checked = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const world::Scenario sc = random_scenario(rng, kFamilies);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task);
    plan::PlannerOptions opt;  // astar-exp
    opt.transition_based = true;
    opt.generalized = plan::PlannerOptions::Generalized::Never;  // one set (generalized: generalized_test.cpp)
    plan::Planner trans(sc, opt);
    (void)trans.plan();
    for (int k = 0; k < 3; ++k) {
      const auto& objs = trans.scenario().objects;
      const auto& regs = trans.scenario().regions;
      const std::string change =
          "move " + objs[rng() % objs.size()].name + " " + regs[rng() % regs.size()].name;
      SCOPED_TRACE(change);
      trans.apply(world::Change::parse(change), plan::Planner::ChangeOrigin::Observed);
      plan::Planner state(trans.scenario());
      state.set_placement(trans.placement(), trans.hand());
      const plan::PlanResult rt = trans.plan();
      const plan::PlanResult rs = state.plan();
      ASSERT_EQ(rt.found, rs.found) << rt.message << " / " << rs.message;
      if (!rt.found) continue;
      EXPECT_NEAR(rt.plan.cost(), rs.plan.cost(), 1e-6);
      check_plan(trans, rt, "euclid");
      ++checked;
    }
  }
  EXPECT_GT(checked, 150);
}

}  // namespace
