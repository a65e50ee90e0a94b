// The trees the planner builds, in every BT variant (docs/bt-variants.md:
// online-action, online-state, offline), before and after replans: their XML
// passes BehaviorTree.CPP's schema (xmllint), has unique TreeObserver paths (the
// state-condition trees repeat names such as "post (state)"), imports back to
// the same XML, and the imported tree ticks like the original against the same
// world (same statuses of every node, same moves started and halted).
#include <gtest/gtest.h>

#include "btcpp_checks.hpp"
#include "rtamp/bt/xml_import.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

// An arm whose moves take three ticks; it logs what it does.
class LoggingRunner final : public ActionRunner {
 public:
  explicit LoggingRunner(world::Placement& world) : world_(world) {}
  bt::Status start(const plan::ActionTuple& t) override {
    log.push_back("start " + t.thing + "->" + t.to);
    world_.things[t.thing].location = kInHand;
    ticks_ = 0;
    return bt::Status::Running;
  }
  bt::Status running(const plan::ActionTuple& t) override {
    if (++ticks_ < 3) return bt::Status::Running;
    world_.things[t.thing].location = t.to;
    log.push_back("done " + t.thing + "->" + t.to);
    return bt::Status::Success;
  }
  void halt(const plan::ActionTuple& t) override { log.push_back("halt " + t.thing + "->" + t.to); }
  std::vector<std::string> log;

 private:
  world::Placement& world_;
  int ticks_ = 0;
};

// "o1 in r2 & o2 in r1" (subtree_builder's port text) back to conditions.
std::vector<plan::Condition> parse_conditions(const std::string& text) {
  std::vector<plan::Condition> out;
  if (text == "true") return out;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find(" & ", at);
    if (end == std::string::npos) end = text.size();
    const std::string lit = text.substr(at, end - at);
    const std::size_t in = lit.find(" in ");
    out.push_back({lit.substr(0, in), lit.substr(in + 4)});
    at = end + 3;
  }
  return out;
}

// Leaves rebuilt from their ports, running moves on `runner`.
bt::NodeRegistry plan_registry(ActionRunner& runner) {
  bt::NodeRegistry r;
  for (const char* type : {"ActionCondition", "StateCondition"}) {
    r.add(type, [type](const bt::NodeSpec& s) {
      const auto conds = parse_conditions(*s.port("conditions"));
      return std::make_unique<bt::Condition>(
          s.name,
          [conds](bt::Node& self) { return holds(conds, self.blackboard().get<world::Placement>(kPlacementKey)); },
          type);
    });
  }
  r.add("Move", [&runner](const bt::NodeSpec& s) {
    auto t = std::make_shared<plan::ActionTuple>();
    t->thing = *s.port("object");
    t->to = *s.port("to");
    auto move = std::make_unique<bt::Action>(
        s.name,
        bt::Action::Callbacks{[t, &runner](bt::Node&) { return runner.start(*t); },
                              [t, &runner](bt::Node&) { return runner.running(*t); },
                              [t, &runner](bt::Node&) { runner.halt(*t); }},
        "Move");
    move->set_interruptible(false);
    return move;
  });
  r.add("StateUpdate", [](const bt::NodeSpec& s) {
    const auto post = parse_conditions(*s.port("effect"));
    return std::make_unique<bt::StateUpdate>(s.name, [post](bt::Node& self) {
      auto& placement = self.blackboard().get<world::Placement>(kPlacementKey);
      for (const plan::Condition& c : post)
        if (auto it = placement.things.find(c.thing); it != placement.things.end()) it->second.location = c.location;
    });
  });
  return r;
}

struct Variant {
  const char* name;
  ConditionMode mode;
  Reconfiguration reconfiguration;
};
constexpr Variant kVariants[] = {{"online-action", ConditionMode::Action, Reconfiguration::Online},
                                 {"online-state", ConditionMode::State, Reconfiguration::Online},
                                 {"offline", ConditionMode::Action, Reconfiguration::Offline}};

std::string statuses(const bt::Tree& t) {
  std::string s;
  t.for_each([&s](const bt::Node& n, int) { s += bt::status_marker(n.status()); });
  return s;
}

// Every file the episode would dump: the first plan and the tree after each replan.
// The planner's ids are not pre-order (PlanTree builds and edits in steps), so the
// importing tree's ids differ: names, ports and structure must not; and a second
// round trip, from pre-order ids, is the identity byte for byte.
void check_file(const bt::Tree& original, const Variant& v) {
  const std::string xml = bt::to_btcpp_xml(original);
  if (bt::testing::have_xmllint()) {
    EXPECT_EQ(bt::testing::schema_errors(xml), "") << xml;
  }
  EXPECT_EQ(bt::testing::repeated_paths(xml), std::vector<std::string>{}) << xml;
  world::Placement dummy;
  LoggingRunner runner(dummy);
  bt::Tree imported;
  imported.set_root(bt::from_btcpp_xml(xml, plan_registry(runner)));
  bt::XmlOptions plain;
  plain.unique_names = false;
  EXPECT_EQ(bt::to_btcpp_xml(imported, plain), bt::to_btcpp_xml(original, plain)) << v.name;
  const std::string again = bt::to_btcpp_xml(imported);
  bt::Tree second;
  second.set_root(bt::from_btcpp_xml(again, plan_registry(runner)));
  EXPECT_EQ(bt::to_btcpp_xml(second), again) << v.name;
}

TEST(XmlPlanTrees, EveryVariantValidatesRoundTripsAndTicksLikeTheOriginal) {
  if (!bt::testing::have_xmllint()) {
    std::printf("xmllint is missing (install libxml2-utils: scripts/install-deps); schema checks skipped\n");
  }
  for (const std::string scenario_name : {"3-block", "3-block-tray"}) {
    for (const Variant& v : kVariants) {
      SCOPED_TRACE(scenario_name + " " + v.name);
      const world::Scenario scenario = world::load_scenario(scenario_name);
      plan::Planner planner(scenario);
      world::Placement world_a = world::initial_placement(scenario), world_b = world_a;
      LoggingRunner runner_a(world_a), runner_b(world_b);
      PlanTree tree(v.mode, v.reconfiguration, runner_a, std::make_shared<bt::SteadyClock>());
      planner.set_placement(world_a, {});
      const auto first = planner.action_tuples(planner.plan().plan);
      ASSERT_FALSE(first.empty());
      tree.set_plan(first);
      check_file(tree.tree(), v);
      const std::string xml = bt::to_btcpp_xml(tree.tree());
      // The imported tree against its own copy of the world, tick by tick.
      bt::Tree imported;
      imported.blackboard().set(kPlacementKey, world_b);
      imported.set_root(bt::from_btcpp_xml(xml, plan_registry(runner_b)));
      for (int i = 0; i < 40; ++i) {
        tree.placement() = world_a;
        imported.blackboard().get<world::Placement>(kPlacementKey) = world_b;
        const bt::Status sa = tree.tick(), sb = imported.tick();
        ASSERT_EQ(sa, sb) << "tick " << i;
        ASSERT_EQ(statuses(tree.tree()), statuses(imported)) << "tick " << i;
        ASSERT_EQ(runner_a.log, runner_b.log) << "tick " << i;
        if (sa == bt::Status::Success) break;
      }
      EXPECT_FALSE(runner_a.log.empty());
      // Replans from other placements (the tree changes in place, ids are kept).
      const std::vector<std::string> places{"r1", "r2"};
      for (int round = 0; round < 4; ++round) {
        world::Placement p = world::initial_placement(scenario);
        int k = round;
        for (auto& [name, thing] : p.things) {
          if (name.rfind("o", 0) == 0) thing.location = places[(k++) % 2];
        }
        planner.set_placement(p, {});
        const plan::PlanResult r = planner.plan();
        if (!r.found) continue;
        tree.set_plan(planner.action_tuples(r.plan));
        check_file(tree.tree(), v);
      }
    }
  }
}

}  // namespace
}  // namespace rtamp::exec
