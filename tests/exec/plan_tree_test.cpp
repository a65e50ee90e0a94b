// The plan's behavior tree (Section III.D): the two subtree forms of Fig. 3,
// Algorithm 2 against a tree built from scratch, deferral of a change that
// would cut a running move, the offline baseline, and Algorithm 1's "can a
// subtree handle this relocation" test for action vs state conditions. Plans
// come from the real planner on the built-in scenarios; the arm is a fake
// ActionRunner whose moves finish when the test says so.
#include "rtamp/exec/plan_tree.hpp"

#include <gtest/gtest.h>

#include <random>

#include "rtamp/plan/planner.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

// A fake arm: a move runs until finish() is called; then it succeeds and the
// thing is at its destination in `world`.
class FakeRunner final : public ActionRunner {
 public:
  explicit FakeRunner(world::Placement& world) : world_(world) {}
  bt::Status start(const plan::ActionTuple& t) override {
    started.push_back(t.action);
    current = t;
    world_.things[t.thing].location = kInHand;
    return bt::Status::Running;
  }
  bt::Status running(const plan::ActionTuple& t) override {
    if (!done) return bt::Status::Running;
    done = false;
    world_.things[t.thing].location = t.to;
    finished.push_back(t.action);
    current.reset();
    return fail_next ? (fail_next = false, bt::Status::Failure) : bt::Status::Success;
  }
  void halt(const plan::ActionTuple& t) override {
    halted.push_back(t.action);
    current.reset();
  }
  void finish() { done = true; }

  std::vector<std::string> started, finished, halted;
  std::optional<plan::ActionTuple> current;
  bool done = false, fail_next = false;

 private:
  world::Placement& world_;
};

// A structural signature of a node: type, name, ports, children — what "the
// same tree" means for Algorithm 2 (ids aside).
std::string signature(const bt::Node& n) {
  std::string s = std::string(n.type_id()) + "(" + n.name();
  for (const bt::Port& p : n.user_ports()) s += " " + p.name + "=" + p.value;
  s += ")[";
  for (const bt::Node* c : n.children()) s += signature(*c) + ",";
  return s + "]";
}

std::vector<std::string> subtree_signatures(const PlanTree& t) {
  std::vector<std::string> out;
  for (const bt::Node* c : t.tree().root()->children()) out.push_back(signature(*c));
  return out;
}

struct Fixture {
  explicit Fixture(const std::string& scenario_name, ConditionMode mode,
                   Reconfiguration reconfiguration = Reconfiguration::Online)
      : scenario(world::load_scenario(scenario_name)),
        planner(scenario),
        world(world::initial_placement(scenario)),
        runner(world),
        tree(mode, reconfiguration, runner, std::make_shared<bt::SteadyClock>()) {}

  std::vector<plan::ActionTuple> plan_from(const world::Placement& p, const std::string& hand = {}) {
    planner.set_placement(p, hand);
    const plan::PlanResult r = planner.plan();
    EXPECT_TRUE(r.found) << r.message;
    return planner.action_tuples(r.plan);
  }
  bt::Status tick() {
    tree.placement() = world;  // perception: the tree sees the world as it is
    return tree.tick();
  }

  world::Scenario scenario;
  plan::Planner planner;
  world::Placement world;
  FakeRunner runner;
  PlanTree tree;
};

std::vector<std::string> actions_of(const std::vector<plan::ActionTuple>& ts) {
  std::vector<std::string> out;
  for (const auto& t : ts) out.push_back(t.action);
  return out;
}

// ---- the two subtree forms (Fig. 3) --------------------------------------------

TEST(SubtreeBuilder, ActionFormSkipsDoneStepsRunsEnabledOnesAndFailsOtherwise) {
  for (ConditionMode mode : {ConditionMode::Action, ConditionMode::State}) {
    SCOPED_TRACE(to_string(mode));
    Fixture f("3-block", mode);
    const auto tuples = f.plan_from(f.world);
    ASSERT_EQ(actions_of(tuples), (std::vector<std::string>{"move(o1, r2)", "move(o2, r2)", "move(o3, r2)"}));
    bt::Tree tree(std::make_shared<bt::Blackboard>(), std::make_shared<bt::SteadyClock>());
    tree.blackboard().set(kPlacementKey, f.world);
    tree.set_root(build_subtree(tuples[0], mode, f.runner));
    // Pre holds: the move starts.
    EXPECT_EQ(tree.tick(), bt::Status::Running);
    EXPECT_EQ(f.runner.started, std::vector<std::string>{"move(o1, r2)"});
    f.runner.finish();
    tree.blackboard().get<world::Placement>(kPlacementKey).things["o1"].location = kInHand;
    EXPECT_EQ(tree.tick(), bt::Status::Success);
    // Post holds: success without moving again.
    tree.blackboard().get<world::Placement>(kPlacementKey).things["o1"].location = "r2";
    EXPECT_EQ(tree.tick(), bt::Status::Success);
    EXPECT_EQ(f.runner.started.size(), 1u);
    // Neither (o1 somewhere else): failure, nothing started.
    tree.blackboard().get<world::Placement>(kPlacementKey).things["o1"].location = "none";
    EXPECT_EQ(tree.tick(), bt::Status::Failure);
    EXPECT_EQ(f.runner.started.size(), 1u);
  }
}

TEST(SubtreeBuilder, StateFormChecksTheWholeStateActionFormOnlyItsObject) {
  Fixture f("3-block", ConditionMode::Action);
  const auto tuples = f.plan_from(f.world);
  world::Placement p = f.world;
  p.things["o3"].location = "r2";  // an unrelated block moved
  EXPECT_TRUE(holds(precondition(tuples[0], ConditionMode::Action), p));
  EXPECT_FALSE(holds(precondition(tuples[0], ConditionMode::State), p));
  EXPECT_EQ(to_string(tuples[0].relaxed_pre), "o1 in r1");
}

TEST(SubtreeBuilder, StateFormWritesThePostStateWhenTheMoveSucceeds) {
  Fixture f("3-block", ConditionMode::State);
  const auto tuples = f.plan_from(f.world);
  bt::Tree tree(std::make_shared<bt::Blackboard>(), std::make_shared<bt::SteadyClock>());
  tree.blackboard().set(kPlacementKey, f.world);
  tree.set_root(build_subtree(tuples[0], ConditionMode::State, f.runner));
  ASSERT_EQ(tree.tick(), bt::Status::Running);
  tree.blackboard().get<world::Placement>(kPlacementKey).things["o1"].location = kInHand;  // C_R
  EXPECT_EQ(tree.tick(), bt::Status::Running);
  f.runner.finish();
  EXPECT_EQ(tree.tick(), bt::Status::Success);
  EXPECT_EQ(*tree.blackboard().get<world::Placement>(kPlacementKey).location_of("o1"), "r2");
}

TEST(SubtreeBuilder, UpdateKeepsIdsAndStructureAndEqualsAFreshBuild) {
  Fixture f("3-block", ConditionMode::Action);
  const auto first = f.plan_from(f.world);
  world::Placement moved = f.world;
  moved.things["o1"].location = "r2";
  moved.things["o2"].location = "r2";
  const auto second = f.plan_from(moved);
  ASSERT_EQ(second.back().action, first.back().action);
  for (ConditionMode mode : {ConditionMode::Action, ConditionMode::State}) {
    auto kept = build_subtree(first.back(), mode, f.runner);
    bt::Tree tree(std::make_shared<bt::Blackboard>(), std::make_shared<bt::SteadyClock>());
    const bt::NodeId id = tree.set_root(std::move(kept));
    std::vector<bt::NodeId> ids_before;
    tree.for_each([&](const bt::Node& n, int) { ids_before.push_back(n.id()); });
    update_subtree(tree.at(id), second.back(), mode, f.runner);
    std::vector<bt::NodeId> ids_after;
    tree.for_each([&](const bt::Node& n, int) { ids_after.push_back(n.id()); });
    EXPECT_EQ(ids_before, ids_after);
    EXPECT_EQ(signature(tree.at(id)), signature(*build_subtree(second.back(), mode, f.runner)));
  }
}

// ---- Algorithm 2 -------------------------------------------------------------------

TEST(PlanTree, SharedSuffixKeepsSubtreesAndTheirIds) {
  Fixture f("3-block", ConditionMode::Action);
  f.tree.set_plan(f.plan_from(f.world));
  const std::vector<bt::NodeId> ids(f.tree.tree().root()->children().size(), 0);
  std::vector<bt::NodeId> before;
  for (const bt::Node* c : f.tree.tree().root()->children()) before.push_back(c->id());
  world::Placement later = f.world;
  later.things["o1"].location = "r2";
  const ReconfigurationReport r = f.tree.set_plan(f.plan_from(later));
  EXPECT_TRUE(r.applied);
  EXPECT_EQ(r.removed, 1u);
  EXPECT_EQ(r.inserted, 0u);
  EXPECT_EQ(r.updated, 2u);
  std::vector<bt::NodeId> after;
  for (const bt::Node* c : f.tree.tree().root()->children()) after.push_back(c->id());
  EXPECT_EQ(after, std::vector<bt::NodeId>(before.begin() + 1, before.end()));
  EXPECT_EQ(f.tree.changes(), 3u + 1u);
}

TEST(PlanTree, ActionAddedInTheMiddleIsOneInsert) {
  // 3-block + an added block: the new plan moves it as well.
  Fixture f("3-block", ConditionMode::Action);
  f.tree.set_plan(f.plan_from(f.world));
  f.planner.apply(world::Change::add_object("o4", "block", "r1"));
  world::Placement now = f.world;
  now.set("o4", "r1", "block");
  const auto tuples = f.plan_from(now);
  ASSERT_EQ(tuples.size(), 4u);
  const ReconfigurationReport r = f.tree.set_plan(tuples);
  EXPECT_TRUE(r.applied);
  EXPECT_EQ(r.inserted + r.removed, f.tree.changes() - 3u);
  EXPECT_LE(r.inserted, 2u);  // the new block's move (and at most one re-ordered step)
  EXPECT_EQ(f.tree.tuples().size(), 4u);
}

// Property: after any sequence of plans, the online tree equals a tree built
// from scratch for the last plan (same actions, conditions and order).
TEST(PlanTree, OnlineResultEqualsAFreshBuildForRandomReplans) {
  for (ConditionMode mode : {ConditionMode::Action, ConditionMode::State}) {
    Fixture f("3-block-tray", mode);
    std::mt19937 rng(7);
    f.tree.set_plan(f.plan_from(f.world));
    const std::vector<std::string> blocks{"o1", "o2", "o3"}, places{"r1", "r2", "r3"};
    for (int round = 0; round < 40; ++round) {
      world::Placement p = f.world;
      for (const auto& b : blocks) p.things[b].location = places[rng() % places.size()];
      p.things["r3"].location = rng() % 2 ? "r1" : "r2";
      // Respect the capacities the planner enforces: at most 3 blocks on the tray.
      const auto tuples = f.plan_from(p);
      const ReconfigurationReport r = f.tree.set_plan(tuples);
      ASSERT_TRUE(r.applied);  // nothing runs: never deferred
      Fixture fresh(f.scenario.name, mode);
      fresh.tree.set_plan(tuples);
      ASSERT_EQ(subtree_signatures(f.tree), subtree_signatures(fresh.tree)) << "round " << round;
    }
  }
}

TEST(PlanTree, ChangeThatWouldCutTheRunningMoveIsDeferredUntilItReturns) {
  Fixture f("3-block", ConditionMode::Action);
  f.tree.set_plan(f.plan_from(f.world));
  ASSERT_EQ(f.tick(), bt::Status::Running);  // move(o1, r2) runs
  ASSERT_EQ(f.tree.running_action(), "move(o1, r2)");
  // A new plan without move(o1, r2) (as if o1 were already done).
  world::Placement later = f.world;
  later.things["o1"].location = "r2";
  const ReconfigurationReport r = f.tree.set_plan(f.plan_from(later));
  EXPECT_FALSE(r.applied);
  EXPECT_TRUE(f.tree.has_pending());
  EXPECT_EQ(f.tree.tuples().size(), 3u);
  EXPECT_FALSE(f.tree.retry_pending()->applied);  // still running
  EXPECT_EQ(f.tick(), bt::Status::Running);
  f.runner.finish();
  EXPECT_EQ(f.tick(), bt::Status::Running);  // the move returns SUCCESS; the root yields
  EXPECT_EQ(f.runner.finished, std::vector<std::string>{"move(o1, r2)"});
  EXPECT_EQ(f.runner.started.size(), 1u);  // the next step waits for the change
  EXPECT_TRUE(f.runner.halted.empty());    // never cut
  // Now the change goes through, and the new plan starts from its first step.
  const auto applied = f.tree.retry_pending();
  ASSERT_TRUE(applied);
  EXPECT_TRUE(applied->applied);
  EXPECT_EQ(applied->removed, 1u);
  EXPECT_FALSE(f.tree.has_pending());
  EXPECT_EQ(f.tree.tuples().size(), 2u);
  EXPECT_EQ(f.tick(), bt::Status::Running);
  EXPECT_EQ(f.runner.started.back(), "move(o2, r2)");
}

TEST(PlanTree, OfflineRebuildsEverythingAndWaitsForTheArm) {
  Fixture f("3-block", ConditionMode::State, Reconfiguration::Offline);
  f.tree.set_plan(f.plan_from(f.world));
  EXPECT_EQ(f.tree.changes(), 3u);
  ASSERT_EQ(f.tick(), bt::Status::Running);
  world::Placement later = f.world;
  later.things["o1"].location = "r2";
  EXPECT_FALSE(f.tree.set_plan(f.plan_from(later)).applied);  // the arm is moving
  f.runner.finish();
  EXPECT_EQ(f.tick(), bt::Status::Running);  // yields: the next step waits for the rebuild
  EXPECT_EQ(f.runner.started.size(), 1u);
  const auto r = f.tree.retry_pending();
  ASSERT_TRUE(r && r->applied);
  EXPECT_EQ(r->removed, 3u);
  EXPECT_EQ(r->inserted, 2u);
  EXPECT_EQ(f.tree.changes(), 3u + 3u + 2u);
  EXPECT_TRUE(f.runner.halted.empty());
}

TEST(PlanTree, EmptyPlanSucceedsAtOnce) {
  Fixture f("3-block", ConditionMode::Action);
  world::Placement done = f.world;
  for (const char* b : {"o1", "o2", "o3"}) done.things[b].location = "r2";
  f.world = done;
  f.tree.set_plan(f.plan_from(done));
  EXPECT_TRUE(f.tree.tuples().empty());
  EXPECT_EQ(f.tick(), bt::Status::Success);
}

// ---- Algorithm 1, line 6: relocation handled by the tree? -------------------------

// Two blocks are done, then the operator puts o1 back in r1. The action-condition
// tree's first subtree (move o1 to r2, relaxed pre "o1 in r1") handles it without
// replanning and redoes the move; the state-condition tree's preconditions name
// the whole state and none matches.
TEST(PlanTree, ActionConditionsHandleABlockMovedBackStateConditionsDoNot) {
  for (ConditionMode mode : {ConditionMode::Action, ConditionMode::State}) {
    SCOPED_TRACE(to_string(mode));
    Fixture f("3-block", mode);
    f.tree.set_plan(f.plan_from(f.world));
    for (int k = 0; k < 2; ++k) {  // move o1, then o2
      ASSERT_EQ(f.tick(), bt::Status::Running);
      f.runner.finish();
    }
    ASSERT_EQ(f.tick(), bt::Status::Running);  // o2's move returns; o3's starts
    ASSERT_EQ(f.runner.finished, (std::vector<std::string>{"move(o1, r2)", "move(o2, r2)"}));
    f.world.things["o1"].location = "r1";  // the operator undoes the first step
    if (mode == ConditionMode::Action) {
      EXPECT_TRUE(f.tree.can_handle(f.world));
      f.runner.finish();
      EXPECT_EQ(f.tick(), bt::Status::Success);  // o3 done; this pass is over
      EXPECT_EQ(f.tick(), bt::Status::Running);  // the next pass redoes move(o1, r2)
      EXPECT_EQ(f.runner.current->action, "move(o1, r2)");
      f.runner.finish();
      f.tick();
      EXPECT_EQ(f.tick(), bt::Status::Success);
      EXPECT_EQ(*f.world.location_of("o1"), "r2");
    } else {
      // o3's move is running; C_R of its subtree names o1 in r2 and fails now.
      EXPECT_FALSE(f.tree.can_handle(f.world));
    }
  }
}

}  // namespace
}  // namespace rtamp::exec
