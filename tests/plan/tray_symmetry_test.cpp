// Interchangeable containers (task::System::set_container_symmetry) against
// brute force: random small scenarios with two or three trays, tasks whose
// atoms sometimes name a tray (which breaks its symmetry) and sometimes only
// classes; optimal costs equal to the oracle's (which knows no symmetry),
// plans legal and accepted (check_plan), the same with symmetry off. The
// capacity diagnosis (plan/lasso_exists.hpp) is compared with a full lasso
// search on the capacity-free TS, as the diagnosis was once made.
#include <gtest/gtest.h>

#include <iostream>
#include <limits>
#include <optional>
#include <random>

#include "plan_checks.hpp"
#include "rtamp/plan/accepting_distance.hpp"
#include "rtamp/plan/cycle_search.hpp"
#include "rtamp/plan/lasso_exists.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/world/generator.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

world::Scenario random_tray_scenario(std::mt19937& rng, const std::vector<std::string>& formulas) {
  for (;;) {
    world::Scenario sc;
    sc.name = "random-trays";
    const int R = 2 + static_cast<int>(rng() % 2);
    const int N = 1 + static_cast<int>(rng() % 3);
    const int C = 2 + static_cast<int>(rng() % 2);
    const double states = std::pow(R + C, N) * std::pow(R, C) * (R + C + 1);
    if (states > 4000) continue;
    for (int i = 0; i < R; ++i) {
      const int cap = 1 + static_cast<int>(rng() % static_cast<unsigned>(N + C + 1));
      const double y = 0.3 * i - 0.3, x = 0.4 + 0.05 * static_cast<double>(rng() % 5);
      sc.regions.push_back(region("r" + std::to_string(i + 1), x, y, cap));
    }
    for (int i = 0; i < C; ++i) {
      world::Container c;
      c.name = "t" + std::to_string(i + 1);
      c.capacity = 1 + static_cast<int>(rng() % 2);
      c.position = sc.regions[static_cast<std::size_t>(1 + i % (R - 1))].center;
      sc.containers.push_back(c);
    }
    for (int i = 0; i < N; ++i) {
      world::Object o;
      o.name = "o" + std::to_string(i + 1);
      o.position = sc.regions[0].center;
      sc.objects.push_back(o);
    }
    sc.task = formulas[rng() % formulas.size()];
    std::set<std::string> atoms;
    collect_atoms(ltl::parse(sc.task), atoms);
    auto rname = [&]() { return "r" + std::to_string(1 + rng() % static_cast<unsigned>(R)); };
    for (const auto& a : atoms) {
      std::string text;
      switch (rng() % 8) {
        case 0: text = "all block in " + rname(); break;
        case 1: text = "any block in " + rname(); break;
        case 2: text = "count block in " + rname() + " >= 2"; break;
        case 3: text = "all tray in " + rname(); break;
        case 4: text = "t1 in " + rname(); break;          // names t1: it leaves the group
        case 5: text = "any block in t2"; break;           // names t2 as a location
        case 6: text = "o1 in " + rname(); break;
        default: text = "all block in " + rname() + " | count block in " + rname() + " >= 1"; break;
      }
      sc.propositions.push_back(proposition(a, text));
    }
    return sc;
  }
}

// The old diagnosis: a full (optimal) lasso search on the capacity-free TS.
bool relaxed_search_finds(const plan::Planner& p, bool symmetry) {
  task::System relaxed(p.scenario(), p.placement(), p.hand(), task::System::Options{true});
  task::Labeling lab(relaxed, p.automaton().atoms, [](const std::string& s) { return world::parse_prop_expr(s); });
  if (symmetry) {
    relaxed.set_symmetry(lab.symmetry_groups());
    relaxed.set_container_symmetry(lab.container_groups());
  }
  const auto model = plan::make_cost_model("unit", p.scenario());
  plan::ProductGraph g(relaxed, lab, p.automaton(), *model, nullptr);
  if (!g.useful(p.automaton().initial)) return false;
  plan::Experience x;
  plan::LassoSearch ls;
  const auto h = plan::algorithm_info(plan::Algorithm::AStar).make_heuristic(g, x);
  plan::SearchStats st;
  const std::vector<plan::NodeId> starts{g.find_or_add(relaxed.canonical(relaxed.initial()), p.automaton().initial)};
  return ls.run(g, x, starts, *h, plan::LassoConfig{true, false}, plan::Termination{plan::SearchLimits{}, 0}, st).found;
}

TEST(TraySymmetry, RandomTrayScenariosMatchBruteForce) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(77);
  int found = 0, none = 0, capacity = 0, grouped = 0;
  const char* models[] = {"euclid", "region", "unit"};
  for (int trial = 0; trial < 300; ++trial) {
    const world::Scenario sc = random_tray_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    std::optional<double> want;
    bool have_want = false;
    for (const auto algo : {plan::Algorithm::AStarExperience, plan::Algorithm::Dijkstra})
      for (const bool symmetry : {true, false}) {
        plan::PlannerOptions opt;
        opt.algorithm = algo;
        opt.cost = model;
        opt.symmetry = symmetry;
        plan::Planner p(sc, opt);
        if (symmetry && p.system().has_container_symmetry()) ++grouped;
        if (!have_want) {
          want = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), model);
          have_want = true;
          want ? ++found : ++none;
        }
        const plan::PlanResult r = p.plan();
        SCOPED_TRACE(std::string(plan::to_string(algo)) + (symmetry ? " symmetry" : " no symmetry"));
        ASSERT_EQ(r.found, want.has_value()) << r.message;
        if (!r.found) {
          if (r.reason == plan::NoPlanReason::Unsatisfiable) continue;
          ASSERT_TRUE(r.reason == plan::NoPlanReason::NoAcceptingCycle || r.reason == plan::NoPlanReason::Capacity)
              << plan::to_string(r.reason);
          if (r.stats.graph_nodes == 0) continue;  // no start state could reach acceptance: not diagnosed
          EXPECT_EQ(r.reason == plan::NoPlanReason::Capacity, relaxed_search_finds(p, symmetry)) << r.message;
          capacity += r.reason == plan::NoPlanReason::Capacity;
          continue;
        }
        EXPECT_NEAR(r.plan.cost(), *want, 1e-6);
        check_plan(p, r, model);
      }
  }
  EXPECT_GT(found, 100);
  EXPECT_GT(none, 3);
  EXPECT_GT(capacity, 0);
  EXPECT_GT(grouped, 100);
}

// A planner's product graph with both symmetry groups, built here.
struct Product {
  Product(const plan::Planner& p, const std::string& model)
      : ts(p.scenario(), p.placement(), p.hand()),
        lab(ts, p.automaton().atoms, [](const std::string& s) { return world::parse_prop_expr(s); }),
        cost_model(plan::make_cost_model(model, p.scenario())) {
    ts.set_symmetry(lab.symmetry_groups());
    ts.set_container_symmetry(lab.container_groups());
    graph.emplace(ts, lab, p.automaton(), *cost_model, nullptr);
  }
  task::System ts;
  task::Labeling lab;
  std::shared_ptr<plan::MotionCostModel> cost_model;
  std::optional<plan::ProductGraph> graph;
};

// The lasso search with the accepting-set bounds on cycles built at the
// first join candidate's search (plan/accepting_distance.hpp; a query builds
// them only after many such searches), against the brute force: the bounds
// must never cost optimality. Patrols are added to the patterns, since only
// tasks with join candidates use them.
TEST(TraySymmetry, CyclesBoundedThroughTheAcceptingSetMatchBruteForce) {
  auto formulas = robot_patterns();
  for (int k = 0; k < 4; ++k) {
    formulas.push_back("G F a & G F b");
    formulas.push_back("G F (a & X b) & G F c");
  }
  std::mt19937 rng(91);
  int found = 0, bounded = 0;
  const char* models[] = {"euclid", "region", "unit"};
  for (int trial = 0; trial < 240; ++trial) {
    const world::Scenario sc = random_tray_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    plan::PlannerOptions opt;
    opt.cost = model;
    plan::Planner p(sc, opt);
    const auto want = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), model);
    Product pr(p, model);
    plan::ProductGraph& g = *pr.graph;
    const task::System& ts = pr.ts;
    if (!g.useful(p.automaton().initial)) {
      EXPECT_FALSE(want.has_value());
      continue;
    }
    plan::Experience x;
    plan::LassoSearch ls;
    const auto h = plan::algorithm_info(plan::Algorithm::AStar).make_heuristic(g, x);
    plan::SearchStats st;
    plan::LassoConfig config;
    config.accepting_bounds_after = 0;
    const std::vector<plan::NodeId> starts{g.find_or_add(ts.canonical(ts.initial()), p.automaton().initial)};
    const auto r = ls.run(g, x, starts, *h, config, plan::Termination{plan::SearchLimits{}, 0}, st);
    ASSERT_EQ(r.found, want.has_value());
    if (!r.found) continue;
    ++found;
    EXPECT_NEAR(r.prefix_cost + r.cycle_cost, *want, 1e-6);
    // The search closed the graph when it searched a join candidate.
    bounded += st.successor_generations == g.size() && st.cycle_searches > 1;
  }
  EXPECT_GT(found, 100);
  EXPECT_GT(bounded, 30);
}

// The bound itself: on closed graphs of random tray scenarios, every node's
// cycle bound is at most its cheapest cycle through an accepting node (a
// cycle search without heuristic), and often equal to it.
TEST(TraySymmetry, AcceptingSetCycleBoundBelowEveryCycle) {
  auto formulas = robot_patterns();
  for (int k = 0; k < 4; ++k) formulas.push_back("G F a & G F b");
  std::mt19937 rng(19);
  int checked = 0, tight = 0;
  const char* models[] = {"euclid", "region", "unit"};
  for (int trial = 0; trial < 200; ++trial) {
    const world::Scenario sc = random_tray_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    plan::Planner p(sc);
    Product pr(p, model);
    plan::ProductGraph& g = *pr.graph;
    const task::System& ts = pr.ts;
    if (!g.useful(p.automaton().initial)) continue;
    (void)g.find_or_add(ts.canonical(ts.initial()), p.automaton().initial);
    const plan::Termination stop{plan::SearchLimits{}, 0};
    plan::Budget budget;
    budget.start(stop, [] { return std::size_t{0}; });
    plan::SearchStats st;
    plan::AcceptingDistance d;
    ASSERT_TRUE(d.build(g, std::numeric_limits<std::size_t>::max(), budget, st));
    if (g.size() > 3000) continue;
    plan::Experience x;
    plan::CycleSearch cycles;
    cycles.begin(g, x, nullptr, budget);
    for (plan::NodeId n = 0; n < g.size(); ++n) {
      const plan::PathCost u = cycles.cheapest(n, plan::kNoPathCost, st);
      const double b = d.cycle_bound(n);
      if (u.c >= plan::kInf) continue;
      ++checked;
      EXPECT_LE(b, u.c + 1e-9) << "node " << n;
      tight += b > 0 && b >= u.c - 1e-9;
    }
  }
  std::cout << checked << " nodes with a cycle, bound tight at " << tight << "\n";
  EXPECT_GT(checked, 5000);
  EXPECT_GT(tight, 200);
}

// find_accepting_lasso against the full search on the capacity-free TS, also
// on the random scenarios without trays.
TEST(TraySymmetry, ExistenceCheckMatchesFullSearch) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(5);
  int exists = 0, not_exists = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const world::Scenario sc = trial % 2 ? random_tray_scenario(rng, formulas) : random_scenario(rng, formulas);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task);
    plan::Planner p(sc);
    for (const bool symmetry : {true, false}) {
      task::System relaxed(p.scenario(), p.placement(), p.hand(), task::System::Options{true});
      task::Labeling lab(relaxed, p.automaton().atoms, [](const std::string& s) { return world::parse_prop_expr(s); });
      if (symmetry) {
        relaxed.set_symmetry(lab.symmetry_groups());
        relaxed.set_container_symmetry(lab.container_groups());
      }
      const auto e = plan::find_accepting_lasso(relaxed, lab, p.automaton(), {p.automaton().initial}, 0, 0);
      ASSERT_FALSE(e.stopped);
      EXPECT_EQ(e.exists, relaxed_search_finds(p, symmetry));
      e.exists ? ++exists : ++not_exists;
    }
  }
  EXPECT_GT(exists, 50);
  EXPECT_GT(not_exists, 3);
}

// A forbidden move into a tray, or of a tray, takes that tray out of its
// group; plans avoid the move and cost what they cost without any symmetry.
TEST(TraySymmetry, AForbiddenMoveTakesATrayOutOfItsGroup) {
  world::GeneratorOptions g;
  g.regions = 4;
  g.objects = 2;
  g.containers = 3;
  g.task = "G F all_in_r2 & G F all_in_r3";
  g.propositions = {{"all_in_r3", "all block in r3"}};
  const world::Scenario sc = world::generate_scenario(g);
  for (const auto& [thing, to] : {std::pair<std::string, std::string>{"o1", "t2"}, {"t3", "r1"}}) {
    SCOPED_TRACE("forbid move(" + thing + ", " + to + ")");
    plan::Planner p(sc);
    p.forbid_move(thing, to);
    const auto r = p.plan();
    const auto& ts = p.system();
    const int moved = ts.find_thing(thing), into = ts.find_location(to);
    EXPECT_EQ(ts.container_group_of(static_cast<unsigned>(ts.is_container_location(static_cast<unsigned>(into))
                                                              ? ts.thing_of_location(static_cast<unsigned>(into))
                                                              : static_cast<unsigned>(moved))),
              -1);
    EXPECT_TRUE(ts.has_container_symmetry());
    plan::PlannerOptions off;
    off.symmetry = false;
    plan::Planner q(sc, off);
    q.forbid_move(thing, to);
    const auto want = q.plan();
    ASSERT_EQ(r.found, want.found);
    if (!r.found) continue;
    EXPECT_NEAR(r.plan.cost(), want.plan.cost(), 1e-9);
    for (const auto& a : p.action_tuples(r.plan)) EXPECT_FALSE(a.thing == thing && a.to == to);
  }
}

}  // namespace
