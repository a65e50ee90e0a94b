// Optimality and validity on hundreds of random small scenarios: every search
// strategy x both graph constructions x the cost models return the cost of an
// independent brute-force search (oracle.hpp), and every plan is legal and
// accepted (automaton and direct LTL semantics). Replans after random changes
// (A* with experience) equal the brute force from the same state.
#include <gtest/gtest.h>

#include "plan_checks.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

const plan::Algorithm kAlgos[] = {plan::Algorithm::Dijkstra, plan::Algorithm::AStar,
                                  plan::Algorithm::AStarExperience};
const plan::GraphConstruction kGraphs[] = {plan::GraphConstruction::Partial, plan::GraphConstruction::Full};

TEST(Optimality, AllStrategiesMatchBruteForce) {
  const auto formulas = robot_patterns();
  ASSERT_GE(formulas.size(), 10u);
  std::mt19937 rng(2024);
  int found = 0, none = 0;
  const char* models[] = {"euclid", "region", "unit"};
  for (int trial = 0; trial < 600; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    std::optional<double> want;
    bool have_want = false;
    for (auto algo : kAlgos)
      for (auto graph : kGraphs) {
        plan::PlannerOptions opt;
        opt.algorithm = algo;
        opt.graph = graph;
        opt.cost = model;
        plan::Planner p(sc, opt);
        if (!have_want) {
          want = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), model);
          have_want = true;
          want ? ++found : ++none;
        }
        const plan::PlanResult r = p.plan();
        SCOPED_TRACE(std::string(plan::to_string(algo)) + "/" + plan::to_string(graph));
        ASSERT_EQ(r.found, want.has_value()) << r.message;
        if (!r.found) {
          EXPECT_TRUE(r.reason == plan::NoPlanReason::NoAcceptingCycle || r.reason == plan::NoPlanReason::Capacity ||
                      r.reason == plan::NoPlanReason::Unsatisfiable)
              << plan::to_string(r.reason);
          continue;
        }
        EXPECT_NEAR(r.plan.cost(), *want, 1e-6);
        check_plan(p, r, model);
      }
  }
  EXPECT_GT(found, 100);
  EXPECT_GT(none, 3);
}

// Footprints bind in the brute force too (found when clang drew other random
// scenarios than gcc): a default tray (0.24 x 0.16) does not fit a region added
// with the default size (0.2 x 0.2), so the cheap plan "carry the tray to o1"
// exists only when the added region is bigger.
TEST(Optimality, AnAddedRegionTooSmallForTheTray) {
  world::Scenario sc;
  sc.name = "added-region";
  sc.regions = {region("r1", 0.35, 0.3, 1), region("r2", 0.75, -0.1, 1)};
  world::Container t1;
  t1.name = "t1";
  t1.capacity = 3;
  t1.position = sc.regions[1].center;
  sc.containers.push_back(t1);
  world::Object o1;
  o1.name = "o1";
  o1.position = sc.regions[0].center;
  sc.objects.push_back(o1);
  sc.propositions = {proposition("o", "any block in r1"), proposition("r", "o1 in r2"),
                     proposition("s", "o1 in t1 | t1 in r2")};
  sc.task = "G(s -> F r) & G !o";
  double cost[2] = {0, 0};
  for (const bool big : {false, true}) {
    SCOPED_TRACE(big ? "0.3 x 0.3 region" : "default region");
    plan::Planner p(sc);
    p.apply(world::Change::parse(big ? "add-region x0 2 -2 3 0.3 0.3" : "add-region x0 2 -2 3"));
    p.apply(world::Change::parse("move o1 x0"));
    const plan::PlanResult r = p.plan();
    ASSERT_TRUE(r.found) << r.message;
    const auto want = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), "euclid");
    ASSERT_TRUE(want.has_value());
    EXPECT_NEAR(r.plan.cost(), *want, 1e-6);
    check_plan(p, r, "euclid");
    bool tray_to_x0 = false;
    for (const auto& a : p.action_tuples(r.plan)) tray_to_x0 |= a.thing == "t1" && a.to == "x0";
    EXPECT_EQ(tray_to_x0, big);
    cost[big] = r.plan.cost();
  }
  EXPECT_LT(cost[1], cost[0] - 0.5);
}

TEST(Optimality, ReplansAfterChangesMatchBruteForce) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(77);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task);
    plan::PlannerOptions opt;  // astar-exp, partial, euclid
    plan::Planner p(sc, opt);
    (void)p.plan();
    for (int k = 0; k < 4; ++k) {
      // A random change of a random kind (when applicable).
      const auto& cur = p.scenario();
      const int kind = static_cast<int>(rng() % 6);
      std::vector<std::string> locs;
      for (const auto& r : cur.regions) locs.push_back(r.name);
      for (const auto& c : cur.containers) locs.push_back(c.name);
      std::string change;
      if (kind <= 1 && !cur.objects.empty()) {
        const auto& o = cur.objects[rng() % cur.objects.size()];
        change = "move " + o.name + " " + locs[rng() % locs.size()];
      } else if (kind == 2 && cur.objects.size() < 3) {
        change = "add n" + std::to_string(trial) + "_" + std::to_string(k) + " block " + locs[rng() % locs.size()];
      } else if (kind == 3 && cur.objects.size() > 1) {
        change = "remove " + cur.objects[rng() % cur.objects.size()].name;
      } else if (kind == 4 && cur.regions.size() < 4 && cur.objects.size() <= 3) {
        // Far from the scenario's regions: regions must be disjoint (world/change.hpp).
        change = "add-region x" + std::to_string(k) + " " + std::to_string(2.0 + k) + " -2.0 3";
      } else if (kind == 5 && !cur.containers.empty()) {
        change = "remove-container t1";
      } else if (kind == 5 && cur.objects.size() <= 2 && cur.regions.size() <= 3) {
        change = "add-container t1 tray " + cur.regions[0].name + " 2";
      } else {
        continue;
      }
      SCOPED_TRACE(change);
      p.apply(world::Change::parse(change), plan::Planner::ChangeOrigin::Observed);
      const plan::PlanResult r = p.plan();
      const auto want = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), "euclid");
      ASSERT_EQ(r.found, want.has_value()) << r.message;
      ++checked;
      if (r.found) {
        EXPECT_NEAR(r.plan.cost(), *want, 1e-6);
        check_plan(p, r, "euclid");
        // Execute the first action, as the robot would, and keep going.
        if (!r.plan.prefix.empty()) p.execute(r.plan.prefix.front().action);
      }
    }
  }
  EXPECT_GT(checked, 200);
}

// Long query sequences on one product graph (relocations and executed steps
// keep the TS, so learned bounds and solved paths pile up): every replan still
// equals the brute force, and solved paths are really used.
// All three closed-form models: `region` has zero-cost moves (into a tray
// standing in the same region), so solved paths may meet zero-cost loops.
TEST(Optimality, ManyReplansOnOneGraphMatchBruteForce) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(4242);
  int checked = 0;
  std::uint64_t reused = 0;
  const char* models[] = {"euclid", "region", "unit"};
  for (int trial = 0; trial < 180; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    const std::string model = models[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    plan::PlannerOptions opt;  // astar-exp, partial
    opt.cost = model;
    plan::Planner p(sc, opt);
    plan::PlanResult r = p.plan();
    for (int k = 0; k < 12; ++k) {
      const auto& cur = p.scenario();
      if (rng() % 2 == 0 && r.found && !r.plan.prefix.empty()) {
        p.execute(r.plan.prefix.front().action);
      } else {
        std::vector<std::string> things, locs;
        for (const auto& o : cur.objects) things.push_back(o.name);
        for (const auto& r2 : cur.regions) locs.push_back(r2.name);
        for (const auto& c : cur.containers) locs.push_back(c.name);
        if (things.empty()) break;
        const std::string t = things[rng() % things.size()], l = locs[rng() % locs.size()];
        SCOPED_TRACE("move " + t + " " + l);
        p.apply(world::Change::relocate(t, l), plan::Planner::ChangeOrigin::Observed);
      }
      r = p.plan();
      const auto want = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), model);
      ASSERT_EQ(r.found, want.has_value()) << r.message << " (query " << k << ")";
      ++checked;
      reused += r.stats.reused_path_edges;
      if (r.found) {
        EXPECT_NEAR(r.plan.cost(), *want, 1e-6) << "query " << k;
        check_plan(p, r, model);
      }
    }
  }
  EXPECT_GT(checked, 1500);
  EXPECT_GT(reused, 150u);
}

}  // namespace
