// Planning from a set of automaton states (Planner::set_automaton_states):
// the plan's cost is the minimum over single-start plans, computed by the
// brute-force oracle once per start state (oracle::min_lasso_from), for all
// three algorithms and both graph constructions, and for A* with experience
// along query sequences that change the set, the state and the set again on
// one product graph. The set survives apply()/set_placement()/execute().
#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

// A random non-empty subset of the automaton's states.
std::vector<std::uint32_t> random_states(std::mt19937& rng, const automata::Automaton& ba) {
  std::vector<std::uint32_t> qs;
  for (std::uint32_t q = 0; q < ba.num_states(); ++q)
    if (rng() % 2 == 0) qs.push_back(q);
  if (qs.empty()) qs.push_back(static_cast<std::uint32_t>(rng() % ba.num_states()));
  return qs;
}

std::string list(const std::vector<std::uint32_t>& qs) {
  std::string s;
  for (auto q : qs) s += std::to_string(q) + " ";
  return s;
}

TEST(AutomatonStates, MultiStartIsTheMinimumOverSingleStarts) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(99);
  const char* models[] = {"euclid", "region", "unit"};
  const plan::Algorithm algos[] = {plan::Algorithm::Dijkstra, plan::Algorithm::AStar,
                                   plan::Algorithm::AStarExperience};
  int found = 0, multi = 0;
  for (int trial = 0; trial < 250; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    plan::PlannerOptions base;
    base.cost = model;
    plan::Planner probe(sc, base);
    const auto qs = random_states(rng, probe.automaton());
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model + " states " + list(qs));
    const auto want = oracle::min_lasso_from(probe.scenario(), probe.placement(), probe.hand(), probe.automaton(),
                                             model, qs);
    if (qs.size() > 1) ++multi;
    for (auto algo : algos)
      for (auto graph : {plan::GraphConstruction::Partial, plan::GraphConstruction::Full}) {
        SCOPED_TRACE(std::string(plan::to_string(algo)) + "/" + plan::to_string(graph));
        plan::PlannerOptions opt = base;
        opt.algorithm = algo;
        opt.graph = graph;
        plan::Planner p(sc, opt);
        p.set_automaton_states(qs);
        const plan::PlanResult r = p.plan();
        ASSERT_EQ(r.found, want.has_value()) << r.message;
        if (!r.found) continue;
        ++found;
        EXPECT_NEAR(r.plan.cost(), *want, 1e-6);
        check_plan(p, r, model);
        // The start state the plan used gives the same cost on its own.
        const auto& first = r.plan.prefix.empty() ? r.plan.cycle.front() : r.plan.prefix.front();
        const auto single = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), model, true,
                                              first.ba_from);
        ASSERT_TRUE(single.has_value());
        EXPECT_NEAR(*single, r.plan.cost(), 1e-6);
      }
  }
  EXPECT_GT(found, 600);
  EXPECT_GT(multi, 100);
}

// Experience across queries whose start sets differ: learned bounds, solved
// paths and cycles from one set stay correct for the next.
TEST(AutomatonStates, ExperienceReplansWithChangingSetsMatchBruteForce) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(1234);
  const char* models[] = {"euclid", "region", "unit"};
  int checked = 0;
  std::uint64_t reused = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    plan::PlannerOptions opt;  // astar-exp, partial
    opt.cost = model;
    plan::Planner p(sc, opt);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    plan::PlanResult r = p.plan();
    for (int k = 0; k < 10; ++k) {
      const int what = static_cast<int>(rng() % 3);
      if (what == 0) {
        p.set_automaton_states(random_states(rng, p.automaton()));
      } else if (what == 1 && r.found && !r.plan.prefix.empty()) {
        p.execute(r.plan.prefix.front().action);
      } else if (!p.scenario().objects.empty()) {
        const auto& cur = p.scenario();
        const std::string t = cur.objects[rng() % cur.objects.size()].name;
        const std::string l = cur.regions[rng() % cur.regions.size()].name;
        p.apply(world::Change::relocate(t, l), plan::Planner::ChangeOrigin::Observed);
      }
      SCOPED_TRACE("query " + std::to_string(k) + " states " + list(p.automaton_states()));
      r = p.plan();
      const auto want = oracle::min_lasso_from(p.scenario(), p.placement(), p.hand(), p.automaton(), model,
                                               p.automaton_states());
      ASSERT_EQ(r.found, want.has_value()) << r.message;
      ++checked;
      reused += r.stats.reused_nodes;
      if (r.found) {
        EXPECT_NEAR(r.plan.cost(), *want, 1e-6);
        check_plan(p, r, model);
      }
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(reused, 0u);
}

TEST(AutomatonStates, DefaultIsTheInitialStateAndIsKept) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  ASSERT_EQ(p.automaton_states(), std::vector<std::uint32_t>{p.automaton().initial});
  std::vector<std::uint32_t> all;
  for (std::uint32_t q = 0; q < p.automaton().num_states(); ++q) all.push_back(q);
  std::vector<std::uint32_t> shuffled(all.rbegin(), all.rend());
  shuffled.push_back(all.front());
  p.set_automaton_states(shuffled);
  EXPECT_EQ(p.automaton_states(), all);  // sorted, without duplicates
  p.apply(world::Change::relocate("o1", "r3"), plan::Planner::ChangeOrigin::Observed);
  EXPECT_EQ(p.automaton_states(), all);
  p.apply(world::Change::add_object("o9", "block", "r1"), plan::Planner::ChangeOrigin::Observed);
  EXPECT_EQ(p.automaton_states(), all);
  const plan::PlanResult r = p.plan();
  ASSERT_TRUE(r.found) << r.message;
  p.set_placement(p.placement(), p.hand());
  EXPECT_EQ(p.automaton_states(), all);
  EXPECT_THROW(p.set_automaton_states({p.automaton().num_states()}), Error);
  EXPECT_EQ(p.automaton_states(), all);
}

TEST(AutomatonStates, NoUsefulStateIsNoAcceptingCycle) {
  world::Scenario sc = world::load_scenario("3-block-tray");
  sc.task = "a U b";  // a is never read; b = all in r2
  world::Proposition a, b;
  a.name = "a";
  a.text = "o1 in r1";
  a.expr = world::parse_prop_expr(a.text);
  b.name = "b";
  b.text = "all block in r2";
  b.expr = world::parse_prop_expr(b.text);
  sc.propositions = {a, b};
  plan::Planner p(sc);
  // Automaton states from which no accepting cycle is reachable.
  std::vector<std::uint32_t> dead;
  {
    plan::ProductGraph g(p.system(), p.labeling(), p.automaton(), p.model(), nullptr);
    for (std::uint32_t q = 0; q < p.automaton().num_states(); ++q)
      if (!g.useful(q)) dead.push_back(q);
  }
  if (dead.empty()) {
    // The translator keeps only useful states: an empty set has the same effect.
    p.set_automaton_states({});
  } else {
    p.set_automaton_states(dead);
  }
  const plan::PlanResult r = p.plan();
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.reason, plan::NoPlanReason::NoAcceptingCycle);
  EXPECT_NE(r.message.find("automaton state"), std::string::npos) << r.message;
  p.set_automaton_states({p.automaton().initial});
  EXPECT_TRUE(p.plan().found);
}

}  // namespace
