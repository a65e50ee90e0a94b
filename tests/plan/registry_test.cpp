// The planner's registry (plan/registry.hpp): every algorithm name round-trips
// through parse_algorithm and plan::to_string, unknown names get a
// did-you-mean, cost models are built by name (ik once the robot layer
// registered it), registering a name again replaces it, and the planner
// resolves PlannerOptions::cost through the registry.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <set>

#include "rtamp/plan/planner.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::plan {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

TEST(Registry, AlgorithmNamesRoundTrip) {
  std::set<std::string> names;
  for (const auto& a : algorithms()) {
    EXPECT_EQ(parse_algorithm(a.name), a.algorithm);
    EXPECT_STREQ(to_string(a.algorithm), a.name);
    EXPECT_EQ(algorithm_info(a.algorithm).name, a.name);
    EXPECT_FALSE(std::string(a.description).empty());
    EXPECT_TRUE(names.insert(a.name).second) << a.name;
  }
  EXPECT_EQ(algorithm_names(), (std::vector<std::string>{"astar-exp", "astar", "dijkstra"}));
  EXPECT_TRUE(algorithm_info(Algorithm::AStarExperience).keeps_experience);
  EXPECT_FALSE(algorithm_info(Algorithm::AStar).keeps_experience);
}

TEST(Registry, UnknownNamesGetADidYouMean) {
  EXPECT_NE(error_of([] { parse_algorithm("astr"); }).find("did you mean 'astar'?"), std::string::npos);
  EXPECT_NE(error_of([] { parse_algorithm("zzzzzzzz"); }).find("expected one of: astar-exp, astar, dijkstra"),
            std::string::npos);
  EXPECT_NE(error_of([] { make_cost_model("eucild"); }).find("did you mean 'euclid'?"), std::string::npos);
}

TEST(Registry, CostModelsByName) {
  for (const std::string n : {"euclid", "region", "unit"}) {
    ASSERT_TRUE(has_cost_model(n));
    EXPECT_EQ(make_cost_model(n)->name(), n);
  }
  robot::register_ik_cost_model();
  robot::register_ik_cost_model();  // idempotent
  const auto names = cost_model_names();
  EXPECT_EQ(std::count(names.begin(), names.end(), "ik"), 1);
  const world::Scenario tray = world::load_scenario("3-block-tray");
  EXPECT_EQ(make_cost_model("ik", tray)->name(), "ik");
  for (const auto& c : cost_models()) EXPECT_FALSE(c.description.empty()) << c.name;
}

TEST(Registry, ReRegisteringReplacesAndThePlannerUsesIt) {
  register_cost_model({"test-double", "twice the unit cost", [](const world::Scenario&) {
                         return std::make_shared<UnitCost>();
                       }});
  register_cost_model({"test-double", "replaced", [](const world::Scenario&) {
                         return std::make_shared<RegionCost>();
                       }});
  int entries = 0;
  for (const auto& c : cost_models())
    if (c.name == "test-double") {
      ++entries;
      EXPECT_EQ(c.description, "replaced");
    }
  EXPECT_EQ(entries, 1);
  PlannerOptions o;
  o.cost = "test-double";
  Planner p(world::load_scenario("3-block"), o);
  EXPECT_EQ(p.model().name(), "region");
  EXPECT_THROW(register_cost_model({"", "no name", nullptr}), Error);
  o.cost = "no-such-model";
  EXPECT_THROW(Planner(world::load_scenario("3-block"), o), Error);
}

TEST(Registry, InfiniteOrHugeTimeLimitsMeanNoLimit) {
  for (const double limit : {std::numeric_limits<double>::infinity(), 1e10, 1e300}) {
    PlannerOptions o;
    o.limits.time_limit = limit;
    Planner p(world::load_scenario("3-block-tray"), o);
    const PlanResult r = p.plan();
    EXPECT_TRUE(r.found) << limit << ": " << r.message;
    EXPECT_FALSE(r.stats.hit_time_limit);
  }
}

}  // namespace
}  // namespace rtamp::plan
