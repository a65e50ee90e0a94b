// Planner::set_task: a new task on a planner that has planned before gives
// the same optimal cost as a planner made cold with that task, checked like a
// scenario's own task (nothing changes on a refusal), and keeps the
// motion-cost cache: the costs the first task's searches computed are not
// asked of the model again.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>

#include "rtamp/plan/planner.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::plan {
namespace {

// euclid's costs, counted, and expensive enough to cache (as ik is).
class Counted final : public MotionCostModel {
 public:
  explicit Counted(const world::Scenario& s) : inner_(make_cost_model("euclid", s)) {}
  std::string name() const override { return "counted"; }
  double cost(const MotionQuery& q) const override {
    ++calls;
    return inner_->cost(q);
  }
  double lower_bound(const MotionQuery& q, bool anywhere) const override { return inner_->lower_bound(q, anywhere); }
  unsigned depends() const override { return inner_->depends(); }
  bool expensive() const override { return true; }
  mutable std::atomic<long> calls{0};

 private:
  std::shared_ptr<MotionCostModel> inner_;
};

world::TaskChange change(const std::string& task) {
  world::TaskChange c;
  c.task = task;
  c.by = "test";
  return c;
}

struct Case {
  std::string scenario, first, second;
};

class PlannerNewTask : public ::testing::TestWithParam<Case> {};

world::Scenario load(const std::string& name) {
  if (name == "gen-5-8") {
    world::GeneratorOptions g;
    g.regions = 5;
    g.objects = 8;
    g.seed = 1;
    return world::generate_scenario(g);
  }
  return world::load_scenario(name);
}

TEST_P(PlannerNewTask, CostsAsAColdPlannerAndTheCacheIsKept) {
  const Case& c = GetParam();
  world::Scenario s = load(c.scenario);
  s.task = c.first;
  PlannerOptions o;
  auto warm_model = std::make_shared<Counted>(s);
  o.model = warm_model;
  Planner warm(s, o);
  const PlanResult first = warm.plan();
  ASSERT_TRUE(first.found) << first.message;
  const long before = warm_model->calls.load();
  const std::size_t cached = warm.cache().size();
  ASSERT_GT(cached, 0u);
  warm.set_task(change(c.second));
  EXPECT_EQ(warm.scenario().task, c.second);
  EXPECT_EQ(warm.automaton_states(), std::vector<std::uint32_t>{warm.automaton().initial});
  const PlanResult again = warm.plan();
  const long warm_calls = warm_model->calls.load() - before;

  world::Scenario fresh = s;
  fresh.task = c.second;
  PlannerOptions oc;
  auto cold_model = std::make_shared<Counted>(fresh);
  oc.model = cold_model;
  Planner cold(fresh, oc);
  const PlanResult direct = cold.plan();
  ASSERT_EQ(again.found, direct.found) << again.message << " / " << direct.message;
  ASSERT_TRUE(direct.found);
  EXPECT_NEAR(again.plan.cost(), direct.plan.cost(), 1e-9);
  // The first task's costs are reused: the new task's search asks the model
  // only for moves the first one never priced.
  EXPECT_LT(warm_calls, cold_model->calls.load()) << "the motion-cost cache was not kept";
  EXPECT_GE(warm.cache().size(), cached);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, PlannerNewTask,
    ::testing::Values(Case{"3-block-tray", "F G all_in_r2", "F G \"all block in r1\""},
                      Case{"3-block", "F G all_in_r2", "F (\"o1 in r1\" & F G all_in_r2)"},
                      Case{"gen-5-8", "F G \"all block in r2\"", "F G \"all block in r3\""}));

TEST(PlannerNewTask, ABadTaskIsRefusedAndNothingChanges) {
  Planner p(world::load_scenario("3-block"));
  const std::string task = p.scenario().task;
  const std::size_t states = p.automaton().num_states();
  EXPECT_THROW(p.set_task(change("F G nope")), Error);
  EXPECT_THROW(p.set_task(change("F G (")), Error);
  world::TaskChange redefine = change("F G all_in_r2");
  world::Proposition prop;
  prop.name = "all_in_r2";
  prop.text = "all block in r1";
  prop.expr = world::parse_prop_expr(prop.text);
  redefine.propositions.push_back(prop);
  try {
    p.set_task(redefine);
    ADD_FAILURE() << "a proposition was redefined";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("already defined"), std::string::npos) << e.message();
  }
  EXPECT_EQ(p.scenario().task, task);
  EXPECT_EQ(p.automaton().num_states(), states);
  EXPECT_TRUE(p.plan().found);
}

TEST(PlannerNewTask, ANewPropositionJoinsTheScenario) {
  Planner p(world::load_scenario("3-block"));
  world::TaskChange c = change("F G in_r1");
  world::Proposition prop;
  prop.name = "in_r1";
  prop.text = "all block in r1";
  prop.expr = world::parse_prop_expr(prop.text);
  c.propositions.push_back(prop);
  p.set_task(c);
  ASSERT_NE(p.scenario().find_proposition("in_r1"), nullptr);
  ASSERT_NE(p.scenario().find_proposition("all_in_r2"), nullptr);
  const PlanResult r = p.plan();
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.plan.cost(), 0) << "every block starts in r1";
  EXPECT_TRUE(p.action_tuples(r.plan).empty());
}

}  // namespace
}  // namespace rtamp::plan
