// The behavior tree that executes a plan, and its reconfiguration when a new
// plan arrives (paper Section III.D, Algorithm 2, and the offline baseline of
// Section V).
//
//   Sequence "plan" (with memory)
//   ├─ subtree(tuple 1)     built by subtree_builder.hpp, one per action tuple,
//   ├─ subtree(tuple 2)     in plan order (prefix, then the cycle's moves)
//   └─ ...
//
// Each subtree succeeds at once when its post-condition already holds, runs
// its move when its precondition holds, and fails otherwise; the root
// therefore SUCCEEDS when every step is done, FAILS when a step can neither be
// skipped nor run (the executor then replans), and is RUNNING while a move
// runs. The root has memory, so a running move is never preempted by an
// earlier sibling; a pass that ends in SUCCESS starts again from the first
// subtree, which is how undone steps are redone without replanning.
//
// Reconfiguration:
//  - Online (Algorithm 2): reconfiguration_script() aligns the new tuples with
//    the subtrees from the back; kept subtrees get their conditions updated in
//    place (same ids), the rest are inserted / removed. If a removal would cut
//    a running, non-interruptible subtree, the whole change is deferred and
//    retried after each tick until that subtree has returned. While a change
//    is pending, the root yields after each finished step (bt::Sequence's
//    yield), so the next step does not start before the change is applied.
//    The executor can ask for the same while it waits for a replan (hold()).
//    A change applied while no move runs restarts the root at the first step.
//  - Offline (baseline): when no move runs, halt the tree, remove every subtree
//    and build the new ones from scratch.
// changes() counts structural changes: subtrees inserted + subtrees removed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/bt/bt.hpp"
#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/plan/action_tuple.hpp"

namespace rtamp::exec {

enum class Reconfiguration { Online, Offline };
const NameTable<Reconfiguration>& reconfigurations();  // online offline

// A tree variant as the command line and the paper's figures name it: a
// condition form with a way of changing the tree.
struct TreeVariant {
  ConditionMode conditions = ConditionMode::Action;
  Reconfiguration reconfiguration = Reconfiguration::Online;
  bool operator==(const TreeVariant&) const = default;
};
const NameTable<TreeVariant>& tree_variants();  // online-action online-state offline

// What one call to set_plan() (or a deferred retry) did.
struct ReconfigurationReport {
  bool applied = false;   // false: deferred (a running subtree would be cut)
  std::size_t inserted = 0, removed = 0, updated = 0;
};

class PlanTree {
 public:
  PlanTree(ConditionMode mode, Reconfiguration reconfiguration, ActionRunner& runner,
           std::shared_ptr<const bt::Clock> clock);

  // Installs a new plan (the first one builds the tree).
  ReconfigurationReport set_plan(const std::vector<plan::ActionTuple>& tuples);
  // Applies a deferred plan if it can now be applied; nullopt if nothing was pending.
  std::optional<ReconfigurationReport> retry_pending();
  bool has_pending() const { return pending_.has_value(); }
  // While held, the root yields after each finished step (no new step starts).
  void hold(bool on) { hold_ = on; }

  bt::Status tick() { return tree_.tick(); }
  bt::Tree& tree() { return tree_; }
  const bt::Tree& tree() const { return tree_; }
  world::Placement& placement() { return tree_.blackboard().get<world::Placement>(kPlacementKey); }

  const std::vector<plan::ActionTuple>& tuples() const { return tuples_; }
  std::size_t changes() const { return changes_; }
  // The action of the subtree whose move is running, or "" if none.
  std::string running_action() const;
  // Algorithm 1 line 6: some subtree's precondition holds in `placement` (or
  // every step's post-condition already does).
  bool can_handle(const world::Placement& placement) const { return !handler(placement).empty(); }
  // The action of the first subtree whose precondition holds, "every step is
  // done" if every post-condition holds, or "" if neither.
  std::string handler(const world::Placement& placement) const;
  ConditionMode mode() const { return mode_; }

 private:
  ReconfigurationReport apply(const std::vector<plan::ActionTuple>& tuples);
  bool any_running() const;

  ConditionMode mode_;
  Reconfiguration reconfiguration_;
  ActionRunner& runner_;
  bt::Tree tree_;
  bt::NodeId root_ = bt::kNoId;
  std::vector<bt::NodeId> subtrees_;  // in order, parallel to tuples_
  std::vector<plan::ActionTuple> tuples_;
  std::optional<std::vector<plan::ActionTuple>> pending_;
  std::size_t changes_ = 0;
  bool hold_ = false;
};

}  // namespace rtamp::exec
