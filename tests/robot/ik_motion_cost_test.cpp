// The `ik` model behind the planner's interface, on the built-in 3-block-tray
// scenario: the adapter's costs are the model's, for every enabled move of the
// initial state, and respect the interface's lower-bound contract.
#include "rtamp/robot/ik_motion_cost.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "rtamp/plan/planner.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::robot {
namespace {

Eigen::Vector3d v(const world::Vec3& x) { return {x[0], x[1], x[2]}; }

TEST(IkMotionCost, CostsEveryMoveOfTheTrayScenario) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const task::System ts(s);
  IkMotionCost ik(IkMotionCost::params_for(s));
  EXPECT_EQ(ik.name(), "ik");
  EXPECT_TRUE(ik.expensive());
  EXPECT_TRUE(ik.depends() & plan::kDependsThing);
  const task::State s0 = ts.initial();
  int moves = 0;
  ts.for_each_move(s0, [&](const task::Action& a) {
    const plan::MotionQuery q = plan::MotionCostModel::query(ts, s0, a);
    const double c = ik.cost(ts, s0, a);
    EXPECT_TRUE(std::isfinite(c)) << ts.action_name(a);
    EXPECT_EQ(c, ik.model().move_cost(v(q.hand), v(q.from), v(q.to), q.container));
    EXPECT_LE(ik.lower_bound(q, false), c);
    EXPECT_LE(ik.lower_bound(q, true), ik.lower_bound(q, false));
    ++moves;
  });
  EXPECT_GT(moves, 0);
  // Blocks at the same location share one cold computation per destination.
  EXPECT_LT(ik.model().cold_computations(), static_cast<std::uint64_t>(moves));
  EXPECT_EQ(ik.cost(ts, s0, task::Action::stay()), 0.0);
}

// `rtamp gen -m M -n N`, its regions on an arc in the UR5's reach, 30° apart (the blocks move with r1).
world::Scenario regions_in_reach(int m, int n) {
  world::GeneratorOptions g;
  g.regions = m;
  g.objects = n;
  world::Scenario s = world::generate_scenario(g);
  const world::Vec3 old = s.regions[0].center;
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const double a = (-60.0 + 30.0 * static_cast<double>(i)) * M_PI / 180.0;
    s.regions[i].center = {0.55 * std::cos(a), 0.55 * std::sin(a), 0};
  }
  for (auto& o : s.objects)
    for (std::size_t k = 0; k < 2; ++k) o.position[k] += s.regions[0].center[k] - old[k];
  return s;
}

// The planner's bounds with `ik` (lower_bound, carry_bound, the transport bound
// without containers and the chain bounds built on them) are admissible: A*
// finds the cost Dijkstra finds, on tasks that move one, all and some of the
// things, with and without a tray.
TEST(IkMotionCost, AStarFindsDijkstrasCost) {
  const std::pair<const char*, std::vector<std::string>> cases[] = {
      {"3-block-tray",
       {"F G all_in_r2", "F G (\"all block in r2\" & \"r3 in r1\")", "F (\"o1 in r2\") & F (\"o2 in r3\")",
        "G F \"o1 in r2\" & G F \"o1 in r1\""}},
      {"3-block",
       {"F G all_in_r2", "F G \"count block in r2 >= 2\"", "F (\"o1 in r2\" & X F \"o3 in r2\")",
        "G F \"all block in r2\" & G F \"all block in r1\"", "F G \"any block in r2\""}},
      {"gen",
       {"F G \"all block in r3\"", "F G (\"count block in r2 >= 2\" & \"o3 in r3\")",
        "F \"all block in r2\" & F \"all block in r3\"", "G F \"any block in r3\" & G F \"o1 in r2\""}},
  };
  for (const auto& [name, tasks] : cases) {
    world::Scenario s = std::string(name) == "gen" ? regions_in_reach(3, 3) : world::load_scenario(name);
    const auto model = std::make_shared<IkMotionCost>(IkMotionCost::params_for(s));
    for (const std::string& task : tasks) {
      s.task = task;
      double cost[2] = {0, 0};
      std::uint64_t expanded[2] = {0, 0};
      for (int i = 0; i < 2; ++i) {
        plan::PlannerOptions o;
        o.model = model;
        o.algorithm = i == 0 ? plan::Algorithm::Dijkstra : plan::Algorithm::AStarExperience;
        plan::Planner planner(s, o);
        const plan::PlanResult r = planner.plan();
        ASSERT_TRUE(r.found) << name << ": " << task << ": " << r.message;
        cost[i] = r.plan.cost();
        expanded[i] = r.stats.expanded;
      }
      EXPECT_NEAR(cost[1], cost[0], 1e-9) << name << ": " << task;
      EXPECT_LE(expanded[1], expanded[0]) << name << ": " << task;
    }
  }
}

// How much the bounds save, as a count: eight blocks from r1 into r3 of five
// regions on an arc expand 13,979 nodes with them (575,235 with lower_bound alone).
TEST(IkMotionCost, TheTransportBoundKeepsTheSearchSmall) {
  world::Scenario s = regions_in_reach(5, 8);
  s.task = "F G \"all block in r3\"";
  plan::PlannerOptions o;
  o.model = std::make_shared<IkMotionCost>(IkMotionCost::params_for(s));
  plan::Planner planner(s, o);
  const plan::PlanResult r = planner.plan();
  ASSERT_TRUE(r.found) << r.message;
  EXPECT_LE(r.stats.expanded, 20000u);
}

}  // namespace
}  // namespace rtamp::robot
