// The Planner facade: the paper's 3-block + tray behaviour, replanning after
// every kind of change equals a cold plan from the same state, the documented
// "no plan" reasons, limits, action tuples.
#include "rtamp/plan/planner.hpp"

#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

world::Object block(const std::string& name, const world::Vec3& at) {
  world::Object o;
  o.name = name;
  o.position = at;
  return o;
}

// Three blocks in r1, a tray in region `tray_region` at (tx, ty), r2 at distance d from r1.
world::Scenario tray_scene(double d, double tx, double ty) {
  world::Scenario sc;
  sc.name = "tray";
  sc.regions.push_back(region("r1", 0.4, 0.3, 4));
  sc.regions.push_back(region("r2", 0.4, 0.3 - d, 4));
  sc.regions.push_back(region("r4", tx, ty, 4));
  world::Container t;
  t.name = "tray";
  t.capacity = 3;
  t.position = {tx, ty, 0};
  sc.containers.push_back(t);
  for (int i = 1; i <= 3; ++i) sc.objects.push_back(block("o" + std::to_string(i), {0.4, 0.3, 0}));
  world::Proposition p;
  p.name = "all_in_r2";
  p.text = "all block in r2";
  p.expr = world::parse_prop_expr(p.text);
  sc.propositions.push_back(p);
  sc.task = "F G all_in_r2";
  return sc;
}

bool uses(plan::Planner& p, const plan::Plan& pl, const std::string& thing) {
  for (const auto& st : pl.prefix)
    if (!st.action.is_stay() && p.system().thing_name(st.action.thing) == thing) return true;
  return false;
}

TEST(Planner, TrayUsedWhenNearAndRegionsFarApart) {
  plan::Planner p(tray_scene(1.0, 0.5, 0.3));  // tray next to r1, r2 1 m away
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  EXPECT_TRUE(uses(p, r.plan, "tray"));
  check_plan(p, r, "euclid");
  // Direct transfer would cost more: compare with the tray's capacity at 0 ... by hand:
  // home (0,0,0.5) -> r1 (0.4,0.3,0): 0.7071; tray plan = 0.7071 + 0.1 (o->tray) + 0.1*2 (hand r4->r1->r4)
  // ... the brute force is the judge:
  EXPECT_NEAR(r.plan.cost(), *oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), "euclid"), 1e-9);
}

TEST(Planner, TrayNotUsedWhenItCostsMore) {
  plan::Planner p(tray_scene(0.3, -1.5, 0.3));  // tray far away, r2 close to r1
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  EXPECT_FALSE(uses(p, r.plan, "tray"));
  int moves = 0;
  for (const auto& st : r.plan.prefix) moves += !st.action.is_stay();
  EXPECT_EQ(moves, 3);
  check_plan(p, r, "euclid");
}

TEST(Planner, BuiltinThreeBlockTrayUsesTheTray) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  EXPECT_TRUE(uses(p, r.plan, "r3"));
  check_plan(p, r, "euclid");
  plan::Planner q(world::load_scenario("3-block"));
  const auto r2 = q.plan();
  ASSERT_TRUE(r2.found);
  EXPECT_GT(r2.plan.cost(), r.plan.cost());
}

TEST(Planner, ReplanAfterEachChangeKindEqualsColdPlan) {
  const std::vector<std::string> changes = {
      "move o2 r1", "add o4 block r1", "remove o1", "move o3 r3", "add-region r9 0.9 0.0 4 0.3 0.3",
      "remove-container r3", "add-container t2 tray r1 3", "move o4 t2", "move t2 r9",
  };
  for (auto algo : {plan::Algorithm::AStarExperience, plan::Algorithm::AStar, plan::Algorithm::Dijkstra}) {
    plan::PlannerOptions opt;
    opt.algorithm = algo;
    plan::Planner p(world::load_scenario("3-block-tray"), opt);
    auto r = p.plan();
    ASSERT_TRUE(r.found);
    p.execute(r.plan.prefix.front().action);  // the robot made progress
    for (const auto& c : changes) {
      SCOPED_TRACE(c);
      p.apply(world::Change::parse(c));
      r = p.plan();
      plan::PlannerOptions cold;
      cold.algorithm = plan::Algorithm::AStar;
      plan::Planner fresh(p.scenario(), p.automaton(), cold);
      fresh.set_placement(p.placement(), p.hand());
      const auto rc = fresh.plan();
      ASSERT_EQ(r.found, rc.found);
      if (r.found) {
        EXPECT_NEAR(r.plan.cost(), rc.plan.cost(), 1e-9);
        check_plan(p, r, "euclid");
      }
    }
  }
}

TEST(Planner, ExperienceReusesTheGraphOnRelocation) {
  plan::Planner exp(world::load_scenario("3-block-tray"));
  plan::PlannerOptions o;
  o.algorithm = plan::Algorithm::AStar;
  plan::Planner cold(world::load_scenario("3-block-tray"), o);
  (void)exp.plan();
  (void)cold.plan();
  for (const char* c : {"move o2 r2", "move o1 r3", "move o2 r1"}) {
    exp.apply(world::Change::parse(c));
    cold.apply(world::Change::parse(c));
    const auto re = exp.plan(), rc = cold.plan();
    ASSERT_TRUE(re.found && rc.found);
    EXPECT_NEAR(re.plan.cost(), rc.plan.cost(), 1e-9);
    EXPECT_GT(re.stats.reused_nodes, 0u);
    EXPECT_LE(re.stats.successor_generations, rc.stats.successor_generations);
  }
}

// Solved paths: once a plan is found, every prefix node knows its exact best
// lasso, so replanning after the robot did a step (or a person did it for the
// robot) follows the recorded plan and expands nothing.
TEST(Planner, ReplanAfterAStepFollowsTheSolvedPath) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  const auto first = p.plan();
  ASSERT_TRUE(first.found);
  ASSERT_GE(first.plan.prefix.size(), 2u);
  p.execute(first.plan.prefix.front().action);
  const auto next = p.plan();
  ASSERT_TRUE(next.found);
  EXPECT_EQ(next.stats.expanded, 0u);
  EXPECT_EQ(next.stats.reused_path_edges, first.plan.prefix.size() - 1);
  EXPECT_NEAR(next.plan.cost(), first.plan.cost() - first.plan.prefix.front().cost, 1e-9);
  ASSERT_EQ(next.plan.prefix.size(), first.plan.prefix.size() - 1);
  for (std::size_t i = 0; i < next.plan.prefix.size(); ++i)
    EXPECT_EQ(p.describe(next.plan.prefix[i].action), p.describe(first.plan.prefix[i + 1].action)) << i;
  // The same from a cold planner placed in that state.
  plan::PlannerOptions o;
  o.algorithm = plan::Algorithm::AStar;
  plan::Planner cold(p.scenario(), p.automaton(), o);
  cold.set_placement(p.placement(), p.hand());
  const auto rc = cold.plan();
  ASSERT_TRUE(rc.found);
  EXPECT_NEAR(next.plan.cost(), rc.plan.cost(), 1e-9);
  EXPECT_EQ(rc.stats.reused_path_edges, 0u);
}

// `rtamp gen --regions M --objects n` with the patrolling task.
world::Scenario patrol_scenario(int regions, int objects) {
  world::GeneratorOptions g;
  g.regions = regions;
  g.objects = objects;
  g.task = "G F all_in_r2 & G F all_in_r3";
  g.propositions = {{"all_in_r3", "all block in r3"}};
  return world::generate_scenario(g);
}

// Patrolling ("G F all_in_r2 & G F all_in_r3") starts in an accepting
// automaton state, so the start node is accepting and gets a cycle search.
// The hand is at home only before the first move, so no cycle returns to the
// start: A* must see that at once instead of exhausting the product graph
// (29,639 expansions in that one search before; Dijkstra, without the bound,
// still does). Since prefixes may join their cycle anywhere, every closed node
// closer than the join point is a candidate with its own bounded cycle search
// (about fifty here, ~18k expansions in all), so the bound is on the
// start node's search alone and on A* staying well below Dijkstra.
TEST(Planner, PatrolFromAnAcceptingStartDoesNotSearchTheWholeGraph) {
  const world::Scenario sc = patrol_scenario(16, 4);
  plan::PlannerOptions o;
  o.algorithm = plan::Algorithm::AStar;
  plan::Planner astar(sc, o);
  const auto r = astar.plan();
  ASSERT_TRUE(r.found);
  {
    // The start node's cycle search alone.
    plan::ProductGraph g(astar.system(), astar.labeling(), astar.automaton(), astar.model(), nullptr);
    plan::GuardHeuristic h(g);
    const plan::NodeId init = g.find_or_add(astar.system().canonical(astar.state()), astar.automaton().initial);
    ASSERT_TRUE(g.accepting(init));
    plan::LassoSearch ls;
    plan::Experience x;
    plan::SearchStats st;
    plan::SearchLimits one;
    one.max_nodes = 2000;  // the first cycle search would need ~30k nodes without the bound
    (void)ls.run(g, x, init, h, plan::LassoConfig{}, plan::Termination{one, 0}, st);
    EXPECT_EQ(x.cycle(init).lower, plan::kInf) << "the start's cycle search did not see that none exists";
  }
  o.algorithm = plan::Algorithm::Dijkstra;
  plan::Planner dijkstra(sc, o);
  const auto d = dijkstra.plan();
  ASSERT_TRUE(d.found);
  EXPECT_GT(d.stats.expanded, 2 * r.stats.expanded);
  EXPECT_NEAR(r.plan.cost(), d.plan.cost(), 1e-9);
  EXPECT_NEAR(check_plan(astar, r, "euclid"), r.plan.cost(), 1e-9);
}

// Long queries report progress (SearchLimits::on_progress); with interval 0
// every clock check reports. Reports of one query grow monotonically, the
// search is not changed by them, and full construction reports its phase.
// Dijkstra: A* plans this patrol in under a hundred expansions, too few to
// check the clock five times.
TEST(Planner, ReportsProgressDuringLongQueries) {
  const world::Scenario sc = patrol_scenario(5, 8);
  for (auto graph : {plan::GraphConstruction::Partial, plan::GraphConstruction::Full}) {
    plan::PlannerOptions o;
    o.algorithm = plan::Algorithm::Dijkstra;
    o.graph = graph;
    plan::Planner quiet(sc, o);
    const auto r0 = quiet.plan();
    ASSERT_TRUE(r0.found);
    std::vector<plan::SearchProgress> reports;
    o.limits.progress_interval = 0;
    o.limits.on_progress = [&](const plan::SearchProgress& p) { reports.push_back(p); };
    plan::Planner loud(sc, o);
    const auto r = loud.plan();
    ASSERT_TRUE(r.found);
    EXPECT_EQ(r.stats.expanded, r0.stats.expanded);
    EXPECT_NEAR(r.plan.cost(), r0.plan.cost(), 1e-9);
    ASSERT_GE(reports.size(), 5u);
    bool constructing = false, searching = false;
    for (std::size_t i = 0; i < reports.size(); ++i) {
      const auto& p = reports[i];
      const std::string phase = p.phase;
      constructing = constructing || phase == "constructing";
      searching = searching || phase == "searching";
      EXPECT_LE(p.graph_nodes, r.stats.graph_nodes);
      EXPECT_LE(p.expanded, r.stats.expanded);
      if (p.best < plan::kInf) {
        EXPECT_GE(p.best, r.plan.cost() - 1e-9);
      }
      if (i > 0) {
        EXPECT_GE(p.seconds, reports[i - 1].seconds);
        EXPECT_GE(p.graph_nodes, reports[i - 1].graph_nodes);
        if (phase == reports[i - 1].phase) {
          EXPECT_GE(p.expanded, reports[i - 1].expanded);
        }
      }
    }
    EXPECT_TRUE(searching);
    EXPECT_EQ(constructing, graph == plan::GraphConstruction::Full);
  }
}

TEST(Planner, NoPlanReasons) {
  auto sc = world::load_scenario("3-block");
  {
    auto s = sc;
    s.task = "F all_in_r2 & G !all_in_r2";
    plan::Planner p(s);
    const auto r = p.plan();
    EXPECT_FALSE(r.found);
    EXPECT_EQ(r.reason, plan::NoPlanReason::Unsatisfiable);
  }
  {
    auto s = sc;  // an atom that is no proposition is bad input (task/validate.hpp), not a plan outcome
    s.task = "F G nothing_here";
    try {
      plan::Planner p(s);
      ADD_FAILURE() << "the planner accepted an unknown atom";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("'nothing_here', which is not a proposition"), std::string::npos) << e.what();
    }
  }
  {
    auto s = sc;
    s.regions[1].capacity = 2;  // r2 cannot hold the three blocks
    plan::Planner p(s);
    const auto r = p.plan();
    EXPECT_EQ(r.reason, plan::NoPlanReason::Capacity);
  }
  {
    auto s = sc;
    s.task = "F G \"o1 in r1\" & F G \"o1 in r2\"";  // satisfiable formula, impossible world
    plan::Planner p(s);
    const auto r = p.plan();
    EXPECT_EQ(r.reason, plan::NoPlanReason::NoAcceptingCycle);
  }
  {
    plan::PlannerOptions o;
    o.limits.max_nodes = 5;
    plan::Planner p(sc, o);
    const auto r = p.plan();
    EXPECT_EQ(r.reason, plan::NoPlanReason::NodeLimit);
    EXPECT_TRUE(r.stats.hit_node_limit);
  }
  {
    plan::PlannerOptions o;
    o.graph = plan::GraphConstruction::Full;
    o.limits.max_nodes = 5;
    plan::Planner p(sc, o);
    EXPECT_EQ(p.plan().reason, plan::NoPlanReason::NodeLimit);
  }
}

TEST(Planner, QuotedAtomsAreProposionExpressions) {
  auto sc = world::load_scenario("3-block");
  sc.task = "F G \"o1 in r2\"";
  plan::Planner p(sc);
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  int moves = 0;
  for (const auto& st : r.plan.prefix) moves += !st.action.is_stay();
  EXPECT_EQ(moves, 1);
  check_plan(p, r, "euclid");
}

TEST(Planner, BadChangesAreErrors) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  EXPECT_THROW(p.apply(world::Change::parse("move nobody r1")), Error);
  EXPECT_THROW(p.apply(world::Change::parse("move o1 nowhere")), Error);
  EXPECT_THROW(p.apply(world::Change::parse("move r3 r3")), Error);
  EXPECT_THROW(p.apply(world::Change::parse("add o1 block r1")), Error);
  EXPECT_THROW(p.apply(world::Change::parse("remove r3")), Error);
  // The rule book of space: r1 (capacity 4) holds three blocks and the tray.
  try {
    p.apply(world::Change::parse("add o4 block r1"));
    ADD_FAILURE() << "a fifth thing in r1 was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot put 'o4' in 'r1'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(p.placement().things.size(), 4u) << "a refused change changes nothing";
  // What a world showed has happened is taken as it is (the reactive loop's case).
  p.apply(world::Change::parse("add o4 block r1"), plan::Planner::ChangeOrigin::Observed);
  EXPECT_EQ(*p.placement().location_of("o4"), "r1");
  EXPECT_THROW(world::Change::parse("jump o1"), Error);
  EXPECT_THROW(world::Change::parse("add-region x a b"), Error);
  EXPECT_THROW(world::Change::parse(""), Error);
  EXPECT_EQ(world::Change::parse("add o9 cup r2").to_string(), "add o9 cup r2");
  // add-region reads back from its text: every digit of the centre, and the size unless it is the default.
  for (const std::string t : {"add-region r9 0.1 -2.5 3", "add-region r9 0.30000000000000004 2 1 0.5 0.25"})
    EXPECT_EQ(world::Change::parse(t).to_string(), t);
  const world::Change sized = world::Change::parse("add-region r9 2 -2 3 0.3 0.25");
  EXPECT_EQ(sized.region.size[0], 0.3);
  EXPECT_EQ(sized.region.size[1], 0.25);
  EXPECT_EQ(sized.region.capacity, 3);
  EXPECT_EQ(world::Change::parse("add-region r9 2 -2").region.size[0], world::Region{}.size[0]);
}

TEST(Planner, ActionTuples) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  const auto tuples = p.action_tuples(r.plan);
  std::size_t moves = 0;
  for (const auto& st : r.plan.prefix) moves += !st.action.is_stay();
  ASSERT_EQ(tuples.size(), moves);  // the cycle is a stay
  for (std::size_t i = 0; i < tuples.size(); ++i) {
    const auto& t = tuples[i];
    EXPECT_EQ(t.pre.size(), 4u);
    EXPECT_EQ(t.relaxed_pre.front(), (plan::Condition{t.thing, t.from}));
    EXPECT_EQ(t.relaxed_post.front(), (plan::Condition{t.thing, t.to}));
    EXPECT_NE(std::find(t.pre.begin(), t.pre.end(), plan::Condition{t.thing, t.from}), t.pre.end());
    EXPECT_NE(std::find(t.post.begin(), t.post.end(), plan::Condition{t.thing, t.to}), t.post.end());
    if (i + 1 < tuples.size()) {
      EXPECT_EQ(t.post, tuples[i + 1].pre);
      EXPECT_EQ(t.hand_after, tuples[i + 1].hand_before);
    }
    if (t.to == "r3") {  // into the tray: where the tray stands is part of the action condition
      ASSERT_EQ(t.relaxed_pre.size(), 2u);
      EXPECT_EQ(t.relaxed_pre[1].thing, "r3");
    }
    EXPECT_FALSE(t.in_cycle);
  }
  EXPECT_EQ(tuples.front().hand_before, "home");
}

}  // namespace
