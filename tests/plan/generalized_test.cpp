// Generalized acceptance in the product: on random small scenarios (with and
// without a tray) and tasks whose automata have two or three acceptance sets,
// the planner searching the generalized automaton returns the cost of the
// brute force on the definition (a prefix, then a closed walk whose edges
// carry every set: oracle::min_lasso_generalized_lex), which on a state-based
// automaton agrees with the state-based brute force; its plans pass
// check_plan (the word accepted by the automaton and the formula); its
// heuristic stays below the brute force; replans with experience equal cold
// plans; the existence check agrees with the full search; and where the
// automata differ it is never dearer than the state-based planner.
#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/automata/accepting_cycles.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/lasso_exists.hpp"
#include "rtamp/plan/registry.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

// Tasks whose generalized automata have 2 or 3 sets (and one that has 1).
const std::vector<std::string> kFamilies = {
    "G F a & G F b",                  // patrol
    "G F a & G F b & G F c",          // patrol of three
    "G F a & G F b & G !c",           // patrol avoiding
    "G (a -> F b) & G F c",           // response under recurrence
    "F G a & G F b",                  // persistence and recurrence
    "G F (a & !b) & G F (b & !c)",    // patrol of conjunctions
    "F (a & F b)",                    // sequence (one set)
};

const plan::Algorithm kAlgos[] = {plan::Algorithm::AStar, plan::Algorithm::AStarExperience,
                                  plan::Algorithm::Dijkstra};

plan::PlannerOptions generalized_options(const std::string& model, plan::Algorithm algo) {
  plan::PlannerOptions opt;
  opt.cost = model;
  opt.algorithm = algo;
  opt.transition_based = true;
  opt.generalized = plan::PlannerOptions::Generalized::Always;
  return opt;
}

TEST(Generalized, TheOracleAgreesWithTheStateBasedBruteForce) {
  std::mt19937 rng(31);
  int found = 0;
  for (int trial = 0; trial < 240; ++trial) {
    const world::Scenario sc = random_scenario(rng, kFamilies);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task);
    plan::Planner state(sc);
    const auto a = oracle::min_lasso_lex(sc, state.placement(), state.hand(), state.automaton(), "euclid");
    const auto b =
        oracle::min_lasso_generalized_lex(sc, state.placement(), state.hand(), state.automaton(), "euclid");
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a) continue;
    ++found;
    EXPECT_NEAR(a->first, b->first, 1e-6);
    EXPECT_EQ(a->second, b->second);
  }
  EXPECT_GT(found, 80);
}

TEST(Generalized, CostsEqualTheBruteForce) {
  std::mt19937 rng(4243);
  const char* models[] = {"euclid", "region", "unit"};
  int found = 0, none = 0, generalized = 0, cheaper = 0, trays = 0;
  for (int trial = 0; trial < 360; ++trial) {
    const world::Scenario sc = random_scenario(rng, kFamilies);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    trays += sc.containers.empty() ? 0 : 1;
    plan::PlannerOptions opt = generalized_options(model, kAlgos[trial % 3]);
    opt.graph = trial % 2 ? plan::GraphConstruction::Full : plan::GraphConstruction::Partial;
    plan::Planner gen(sc, opt);
    const automata::Automaton& ba = gen.automaton();
    ASSERT_FALSE(ba.state_based);
    generalized += ba.num_sets >= 2;
    const auto want = oracle::min_lasso_generalized_lex(gen.scenario(), gen.placement(), gen.hand(), ba, model);
    const plan::PlanResult r = gen.plan();
    ASSERT_EQ(r.found, want.has_value()) << r.message;
    plan::PlannerOptions sopt;
    sopt.cost = model;
    plan::Planner state(sc, sopt);
    const plan::PlanResult rs = state.plan();
    ASSERT_EQ(rs.found, r.found) << rs.message;
    if (!want) {
      ++none;
      EXPECT_EQ(r.reason, rs.reason) << r.message;
      continue;
    }
    ++found;
    EXPECT_NEAR(r.plan.cost(), want->first, 1e-6);
    EXPECT_LE(r.plan.cost(), rs.plan.cost() + 1e-6);
    cheaper += r.plan.cost() < rs.plan.cost() - 1e-6;
    check_plan(gen, r, model);
  }
  EXPECT_GT(found, 200);
  EXPECT_GT(none, 3);
  EXPECT_GT(generalized, 150);  // the generalized form is chosen, not only one set
  EXPECT_GT(trays, 60);
  std::printf("generalized automata %d of 360; plans %d, none %d; cheaper than state-based %d\n", generalized,
              found, none, cheaper);
}

// h(s, q) <= the best lasso from (s, q), and cycle_bound <= the cheapest
// closed walk from (s, q) that takes every set, from random states and every
// useful automaton state, against the brute force on the definition.
TEST(Generalized, HeuristicAdmissibleAgainstBruteForce) {
  std::mt19937 rng(8);
  int checked = 0, positive = 0, cycle_positive = 0;
  for (int trial = 0; trial < 240; ++trial) {
    world::Scenario sc = random_scenario(rng, kFamilies);
    if (trial % 2 && sc.containers.empty()) make_forcing_patrol(sc, trial % 4 == 1 ? 2 : 3);
    for (const char* model : {"euclid", "region", "unit"}) {
      plan::Planner p(sc, generalized_options(model, plan::Algorithm::AStar));
      const auto [pl, hand] = place_randomly(rng, p);
      const task::State s = p.state();
      const auto cost = plan::make_cost_model(model);
      plan::ProductGraph g(p.system(), p.labeling(), p.automaton(), *cost, nullptr);
      plan::GuardHeuristic h(g);
      for (std::uint32_t q = 0; q < p.automaton().num_states(); ++q) {
        if (!g.useful(q)) continue;
        const auto lasso = oracle::min_lasso_generalized_lex(p.scenario(), pl, hand, p.automaton(), model, q);
        if (!lasso) continue;
        const double est = h.evaluate(s, q);
        EXPECT_LE(est, lasso->first + 1e-9) << sc.task << " q=" << q << " model " << model;
        ++checked;
        positive += est > 0;
        const oracle::Product prod(p.scenario(), pl, hand, p.automaton(), model, true, q);
        const double u = oracle::cheapest_accepting_walk(prod, 0, p.automaton().cycle_marks_all()).first;
        expect_cycle_bound(h, g, s, q, u, sc.task + " model " + model, checked, cycle_positive);
      }
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(positive, 100);
  EXPECT_GT(cycle_positive, 20);
}

// Replans on one generalized planner (experience kept) after the robot moved
// things: each equals a cold generalized plan from the same placement.
TEST(Generalized, ReplansEqualColdPlans) {
  std::mt19937 rng(98);
  int checked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const world::Scenario sc = random_scenario(rng, kFamilies);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task);
    plan::Planner warm(sc, generalized_options("euclid", plan::Algorithm::AStarExperience));
    (void)warm.plan();
    for (int k = 0; k < 3; ++k) {
      const auto& objs = warm.scenario().objects;
      const auto& regs = warm.scenario().regions;
      const std::string change = "move " + objs[rng() % objs.size()].name + " " + regs[rng() % regs.size()].name;
      SCOPED_TRACE(change);
      warm.apply(world::Change::parse(change), plan::Planner::ChangeOrigin::Observed);
      plan::Planner cold(warm.scenario(), generalized_options("euclid", plan::Algorithm::AStar));
      cold.set_placement(warm.placement(), warm.hand());
      const plan::PlanResult rw = warm.plan();
      const plan::PlanResult rc = cold.plan();
      ASSERT_EQ(rw.found, rc.found) << rw.message << " / " << rc.message;
      if (!rw.found) continue;
      EXPECT_NEAR(rw.plan.cost(), rc.plan.cost(), 1e-6);
      check_plan(warm, rw, "euclid");
      ++checked;
    }
  }
  EXPECT_GT(checked, 120);
}

// find_accepting_lasso on the generalized automaton against the brute force.
TEST(Generalized, ExistenceCheckMatchesTheBruteForce) {
  std::mt19937 rng(6);
  int exists = 0, not_exists = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const world::Scenario sc = random_scenario(rng, kFamilies);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task);
    plan::Planner p(sc, generalized_options("unit", plan::Algorithm::AStar));
    const task::System& ts = p.system();
    const auto e = plan::find_accepting_lasso(ts, p.labeling(), p.automaton(), {p.automaton().initial}, 0, 0);
    ASSERT_FALSE(e.stopped);
    const bool want = oracle::min_lasso_generalized_lex(p.scenario(), p.placement(), p.hand(), p.automaton(),
                                                        "unit").has_value();
    EXPECT_EQ(e.exists, want);
    e.exists ? ++exists : ++not_exists;
  }
  EXPECT_GT(exists, 100);
  EXPECT_GT(not_exists, 3);
}

// states_on_accepting_cycles and useful_states on random automata with 0-3
// sets (and state-based ones) against a search over (state, sets taken).
TEST(Generalized, AcceptingCyclesMatchASearchOverTheSetsTaken) {
  std::mt19937 rng(12);
  int on = 0, off = 0;
  for (int trial = 0; trial < 400; ++trial) {
    automata::Automaton a;
    a.atoms = {"a", "b"};
    const std::uint32_t n = 1 + rng() % 6;
    a.state_based = trial % 5 == 0;
    a.num_sets = a.state_based ? 1 : rng() % 4;
    for (std::uint32_t q = 0; q < n; ++q) a.add_state(a.state_based && rng() % 3 == 0);
    for (std::uint32_t q = 0; q < n; ++q)
      for (int k = static_cast<int>(rng() % 3); k >= 0; --k) {
        automata::Cube c;
        if (rng() % 4 == 0) c = {1, 1};  // a false guard: never taken
        const automata::Marks m = a.state_based ? (a.state_accepting[q] ? 1u : 0u) : rng() % (a.all_marks() + 1);
        a.add_edge(q, static_cast<std::uint32_t>(rng() % n), c, m);
      }
    const auto got_on = automata::states_on_accepting_cycles(a);
    const auto got_useful = automata::useful_states(a);
    const automata::Marks all = a.cycle_marks_all();
    // seen[q0][(q, m)]: (q, m) is reachable by >= 1 edge from (q0, no set).
    std::vector<std::vector<bool>> seen(n);
    for (std::uint32_t q0 = 0; q0 < n; ++q0) {
      seen[q0].assign(std::size_t{n} * (all + 1), false);
      std::vector<std::size_t> todo;
      auto step = [&](std::uint32_t q, automata::Marks m) {
        for (const auto& e : a.edges[q]) {
          if (e.guard.is_false()) continue;
          const std::size_t id = std::size_t{e.dst} * (all + 1) + (m | a.cycle_marks(e));
          if (!seen[q0][id]) {
            seen[q0][id] = true;
            todo.push_back(id);
          }
        }
      };
      step(q0, 0);
      while (!todo.empty()) {
        const std::size_t id = todo.back();
        todo.pop_back();
        step(static_cast<std::uint32_t>(id / (all + 1)), static_cast<automata::Marks>(id % (all + 1)));
      }
    }
    auto want_on = [&](std::uint32_t q) { return bool(seen[q][std::size_t{q} * (all + 1) + all]); };
    for (std::uint32_t q0 = 0; q0 < n; ++q0) {
      EXPECT_EQ(got_on[q0], want_on(q0)) << "trial " << trial << " q" << q0;
      bool want_useful = want_on(q0);
      for (std::uint32_t p = 0; p < n; ++p)
        for (automata::Marks m = 0; m <= all; ++m) want_useful = want_useful || (want_on(p) && seen[q0][std::size_t{p} * (all + 1) + m]);
      EXPECT_EQ(got_useful[q0], want_useful) << "trial " << trial << " q" << q0;
      want_on(q0) ? ++on : ++off;
    }
  }
  EXPECT_GT(on, 100);
  EXPECT_GT(off, 100);
}

}  // namespace
