// The planner checks what a motion-cost model gives it (plan/cost_check.hpp):
// a NaN or negative cost, and a NaN, infinite or negative bound, is an
// rtamp::Error out of Planner::plan naming the model, the edge and the value,
// for every algorithm and graph construction; +infinity is a move the model
// cannot do. And the limits of a query (plan/termination.hpp SearchLimits): the
// memory limit and the node limit stop it with their own reason and a message
// that says a plan may still exist.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "rtamp/plan/planner.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Regions r1 (where o1 and o2 start), r2, r3; o1 of class red, o2 and o3 of class block.
world::Scenario scene(const std::string& task) {
  return world::parse_scenario(R"(name: costs
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.30, 0.30], capacity: 5}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.30, 0.30], capacity: 5}
  - {name: r3, center: [0.60, 0.0, 0], size: [0.30, 0.20], capacity: 5}
objects:
  - {name: o1, class: red, position: [0.36, 0.40, 0], size: [0.04, 0.04, 0.04]}
  - {name: o2, class: block, position: [0.42, 0.40, 0], size: [0.04, 0.04, 0.04]}
  - {name: o3, class: block, position: [0.48, 0.40, 0], size: [0.04, 0.04, 0.04]}
propositions:
  o1_in_r2: "o1 in r2"
  o1_in_r3: "o1 in r3"
  blocks_in_r2: "all block in r2"
task: ")" + task + "\"\n",
                               "<test>");
}

// Euclid's values, except those set to a bad value: every cost (or only those
// of moves to `to_x`), every lower bound, carry bound or transport bound.
struct Spoilt : plan::MotionCostModel {
  plan::EuclidCost euclid;
  double cost_value = 0;
  bool bad_cost = false;
  double to_x = kNaN;  // bad only for moves to a point with this x (NaN: every move)
  double lower = 0, carry = 0, transport = 0;
  bool bad_lower = false, bad_carry = false, bad_transport = false;

  std::string name() const override { return "spoilt"; }
  double cost(const plan::MotionQuery& q) const override {
    return bad_cost && (std::isnan(to_x) || q.to[0] == to_x) ? cost_value : euclid.cost(q);
  }
  double lower_bound(const plan::MotionQuery& q, bool anywhere) const override {
    return bad_lower ? lower : euclid.lower_bound(q, anywhere);
  }
  unsigned depends() const override { return euclid.depends(); }
  bool expensive() const override { return false; }
  double carry_bound(const world::Vec3& a, const world::Vec3& b) const override {
    return bad_carry ? carry : euclid.carry_bound(a, b);
  }
  double transport_bound(const plan::TransportQuery& t) const override {
    return bad_transport ? transport : plan::MotionCostModel::transport_bound(t);
  }
};

plan::PlannerOptions with(std::shared_ptr<Spoilt> m, plan::Algorithm a = plan::Algorithm::AStar,
                          plan::GraphConstruction g = plan::GraphConstruction::Partial) {
  plan::PlannerOptions o;
  o.model = std::move(m);
  o.algorithm = a;
  o.graph = g;
  o.symmetry = false;
  return o;
}

// The message of the rtamp::Error plan() throws ("" if none).
std::string plan_error(plan::Planner& p) {
  try {
    (void)p.plan();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CostCheck, ANegativeOrNaNCostIsAnErrorNamingTheModelTheEdgeAndTheValue) {
  for (const double bad : {-1.0, kNaN, -kInfinity}) {
    const std::string value = std::isnan(bad) ? "nan" : bad < -1 ? "-inf" : "-1";
    for (const auto a : {plan::Algorithm::Dijkstra, plan::Algorithm::AStar, plan::Algorithm::AStarExperience})
      for (const auto g : {plan::GraphConstruction::Partial, plan::GraphConstruction::Full}) {
        auto m = std::make_shared<Spoilt>();
        m->bad_cost = true;
        m->cost_value = bad;
        plan::Planner p(scene("F o1_in_r2"), with(m, a, g));
        const std::string e = plan_error(p);
        SCOPED_TRACE(value + " " + plan::to_string(a) + " " + plan::to_string(g));
        EXPECT_TRUE(has(e, "motion-cost model 'spoilt' returned " + value + " for move(o")) << e;
        EXPECT_TRUE(has(e, " from r1, hand at home): a cost must be >= 0")) << e;
        EXPECT_EQ(p.options().algorithm, a);  // the options are the user's after the error
      }
  }
}

TEST(CostCheck, TheErrorNamesTheEdgeWhoseCostIsBad) {
  auto m = std::make_shared<Spoilt>();
  m->bad_cost = true;
  m->cost_value = -1;
  m->to_x = 0.60;  // r3
  plan::Planner p(scene("F o1_in_r2"), with(m));
  const std::string e = plan_error(p);
  EXPECT_TRUE(has(e, "returned -1 for move(o1, r3) (o1 from r1, hand at home)") ||
              has(e, "returned -1 for move(o2, r3) (o2 from r1, hand at home)") ||
              has(e, "returned -1 for move(o3, r3) (o3 from r1, hand at home)"))
      << e;
}

TEST(CostCheck, AnInfiniteCostIsAMoveTheModelCannotDo) {
  auto m = std::make_shared<Spoilt>();
  m->bad_cost = true;
  m->cost_value = kInfinity;
  m->to_x = 0.40;  // r1 and r2
  {
    plan::Planner p(scene("F o1_in_r3"), with(m));
    const auto r = p.plan();
    ASSERT_TRUE(r.found) << r.message;
    EXPECT_TRUE(std::isfinite(r.plan.cost()));
  }
  for (const auto a : {plan::Algorithm::Dijkstra, plan::Algorithm::AStar, plan::Algorithm::AStarExperience}) {
    plan::Planner p(scene("F o1_in_r2"), with(m, a));
    const auto r = p.plan();
    EXPECT_FALSE(r.found);
    EXPECT_EQ(r.reason, plan::NoPlanReason::NoAcceptingCycle) << r.message;
  }
}

TEST(CostCheck, ALowerBoundThatIsNaNInfiniteOrNegativeIsAnError) {
  for (const double bad : {kNaN, kInfinity, -1.0})
    for (const auto a : {plan::Algorithm::AStar, plan::Algorithm::AStarExperience}) {
      auto m = std::make_shared<Spoilt>();
      m->bad_lower = true;
      m->lower = bad;
      plan::Planner p(scene("F o1_in_r2"), with(m, a));
      const std::string e = plan_error(p);
      EXPECT_TRUE(has(e, "motion-cost model 'spoilt' returned " + format_number(bad) +
                             " as lower_bound for bringing o1 from r1 to r2 (hand at home): a lower bound must be "
                             "finite and >= 0"))
          << e;
      // Through the default transport_bound (a class atom), the thing is named too.
      plan::Planner q(scene("F blocks_in_r2"), with(m, a));
      const std::string f = plan_error(q);
      EXPECT_TRUE(has(f, "as lower_bound for bringing o2 from r1 to r2") ||
                  has(f, "as lower_bound for bringing o3 from r1 to r2"))
          << f;
    }
}

TEST(CostCheck, OtherBoundsAreCheckedToo) {
  {
    auto m = std::make_shared<Spoilt>();
    m->bad_transport = true;
    m->transport = kNaN;
    plan::Planner p(scene("F blocks_in_r2"), with(m));
    const std::string e = plan_error(p);
    EXPECT_TRUE(has(e, "returned nan as transport_bound for 2 of 2 things into r2: a bound must be finite")) << e;
  }
  {
    auto m = std::make_shared<Spoilt>();
    m->bad_carry = true;
    m->carry = -2;
    plan::Planner p(scene("G F o1_in_r2 & G F o1_in_r3"), with(m));
    const std::string e = plan_error(p);
    EXPECT_TRUE(has(e, "returned -2 as carry_bound from r")) << e;
  }
}

// `objects` blocks to bring to r2 and to r3, five regions at random: without
// symmetry reduction, five give about 10,000 product nodes (Dijkstra: 25,000).
// The limit tests take six or seven: with five, A*'s bounds find the plan in
// fewer than 128 expansions, before the first memory check.
world::Scenario two_goals(int objects = 5) {
  world::GeneratorOptions g;
  g.regions = 5;
  g.objects = objects;
  g.layout = world::GeneratorOptions::Layout::Random;
  g.seed = 3;
  g.propositions = {{"all_in_r3", "all object in r3"}};
  g.task = "F all_in_r2 & F all_in_r3";
  return world::generate_scenario(g);
}

plan::PlannerOptions unreduced(plan::Algorithm a, plan::GraphConstruction g = plan::GraphConstruction::Partial) {
  plan::PlannerOptions o;
  o.algorithm = a;
  o.graph = g;
  o.symmetry = false;
  return o;
}

TEST(SearchLimits, TheMemoryLimitHasADocumentedDefault) {
  EXPECT_EQ(plan::PlannerOptions{}.limits.max_memory_bytes, std::size_t{4} << 30);
}

TEST(SearchLimits, AQueryOverItsMemoryLimitStopsWithThatReasonNotNoPlan) {
  for (const auto a : {plan::Algorithm::Dijkstra, plan::Algorithm::AStar, plan::Algorithm::AStarExperience})
    for (const auto g : {plan::GraphConstruction::Partial, plan::GraphConstruction::Full}) {
      SCOPED_TRACE(std::string(plan::to_string(a)) + " " + plan::to_string(g));
      plan::PlannerOptions o = unreduced(a, g);
      o.limits.max_memory_bytes = 64 << 10;
      // A* on a partial graph needs seven blocks to pass its first memory
      // check (128 expansions); the full constructions would be slow with seven.
      const int blocks = a != plan::Algorithm::Dijkstra && g == plan::GraphConstruction::Partial ? 7 : 6;
      plan::Planner p(two_goals(blocks), o);
      const auto r = p.plan();
      EXPECT_FALSE(r.found);
      EXPECT_EQ(r.reason, plan::NoPlanReason::MemoryLimit) << r.message;
      EXPECT_STREQ(plan::to_string(r.reason), "memory-limit");
      EXPECT_TRUE(r.stats.hit_memory_limit);
      EXPECT_TRUE(has(r.message, (g == plan::GraphConstruction::Full ? "the full construction" : "the search") +
                                     std::string(" stopped at its memory limit (64 KiB) after ")))
          << r.message;
      EXPECT_TRUE(has(r.message, "whether a plan exists is unknown")) << r.message;
      // Checked every 128 expansions (256 in the full construction): a little above the limit at most.
      EXPECT_LT(r.stats.memory_bytes, std::size_t{4} << 20);
      // The same query without a limit has a plan.
      o.limits.max_memory_bytes = 0;
      plan::Planner unlimited(two_goals(blocks), o);
      EXPECT_TRUE(unlimited.plan().found);
    }
}

TEST(SearchLimits, TheNodeLimitSaysHowFarTheSearchGot) {
  plan::PlannerOptions o = unreduced(plan::Algorithm::AStar);
  o.limits.max_nodes = 1000;
  plan::Planner p(two_goals(6), o);
  const auto r = p.plan();
  EXPECT_EQ(r.reason, plan::NoPlanReason::NodeLimit);
  EXPECT_TRUE(has(r.message, "the search stopped at its node limit (1,000 nodes) after ")) << r.message;
  EXPECT_TRUE(has(r.message, " expansions (")) << r.message;
  EXPECT_TRUE(has(r.message, "whether a plan exists is unknown")) << r.message;
}

// astar-exp keeps its product graph between queries; one that holds half the
// memory limit when a query starts is dropped, so that it cannot grow until
// every query stops at the limit.
TEST(SearchLimits, AKeptGraphOverHalfTheMemoryLimitIsDropped) {
  const plan::PlannerOptions free = unreduced(plan::Algorithm::AStarExperience);
  plan::Planner probe(two_goals(), free);
  const auto first = probe.plan();
  ASSERT_TRUE(first.found);
  const auto again = probe.plan();
  EXPECT_GT(again.stats.reused_nodes, 0u);

  plan::PlannerOptions o = free;
  o.limits.max_memory_bytes = first.stats.memory_bytes;  // the first query fits exactly
  plan::Planner p(two_goals(), o);
  const auto r1 = p.plan();
  ASSERT_TRUE(r1.found) << r1.message;
  const auto r2 = p.plan();
  ASSERT_TRUE(r2.found) << r2.message;
  EXPECT_EQ(r2.stats.reused_nodes, 0u);
  EXPECT_NEAR(r2.plan.cost(), r1.plan.cost(), 1e-9);
}

}  // namespace
