#include "rtamp/exec/plan_tree.hpp"

#include "rtamp/exec/reconfiguration_script.hpp"

namespace rtamp::exec {

const NameTable<Reconfiguration>& reconfigurations() {
  static const NameTable<Reconfiguration> t = {
      {"online", Reconfiguration::Online, "Algorithm 2: update, insert and remove subtrees between moves"},
      {"offline", Reconfiguration::Offline, "rebuild the whole tree from scratch (the paper's baseline)"},
  };
  return t;
}

const NameTable<TreeVariant>& tree_variants() {
  static const NameTable<TreeVariant> t = {
      {"online-action", {ConditionMode::Action, Reconfiguration::Online}, "Algorithm 2 with action conditions"},
      {"online-state", {ConditionMode::State, Reconfiguration::Online}, "Algorithm 2 with full-state conditions"},
      {"offline", {ConditionMode::Action, Reconfiguration::Offline}, "rebuild the tree from scratch"},
  };
  return t;
}

PlanTree::PlanTree(ConditionMode mode, Reconfiguration reconfiguration, ActionRunner& runner,
                   std::shared_ptr<const bt::Clock> clock)
    : mode_(mode), reconfiguration_(reconfiguration), runner_(runner),
      tree_(std::make_shared<bt::Blackboard>(), std::move(clock)) {
  tree_.blackboard().set(kPlacementKey, world::Placement{});
  auto root = std::make_unique<bt::Sequence>("plan");
  // A deferred change (or a plan the executor awaits) goes in between two steps.
  root->set_yield([this] { return pending_.has_value() || hold_; });
  root_ = tree_.set_root(std::move(root));
}

bool PlanTree::any_running() const {
  for (bt::NodeId id : subtrees_)
    if (tree_.at(id).status() == bt::Status::Running) return true;
  return false;
}

std::string PlanTree::running_action() const {
  for (std::size_t i = 0; i < subtrees_.size(); ++i)
    if (tree_.at(subtrees_[i]).status() == bt::Status::Running) return tuples_[i].action;
  return {};
}

std::string PlanTree::handler(const world::Placement& placement) const {
  bool all_done = !tuples_.empty();
  for (const plan::ActionTuple& t : tuples_) {
    if (holds(precondition(t, mode_), placement)) return t.action;
    const auto& post = mode_ == ConditionMode::State ? t.post : t.relaxed_post;
    all_done = all_done && holds(post, placement);
  }
  return all_done ? "every step is done" : "";
}

ReconfigurationReport PlanTree::set_plan(const std::vector<plan::ActionTuple>& tuples) {
  pending_.reset();
  ReconfigurationReport r = apply(tuples);
  if (!r.applied) pending_ = tuples;
  return r;
}

std::optional<ReconfigurationReport> PlanTree::retry_pending() {
  if (!pending_) return std::nullopt;
  ReconfigurationReport r = apply(*pending_);
  if (r.applied) pending_.reset();
  return r;
}

ReconfigurationReport PlanTree::apply(const std::vector<plan::ActionTuple>& tuples) {
  ReconfigurationReport report;
  if (reconfiguration_ == Reconfiguration::Offline) {
    if (any_running()) return report;  // rebuild when the arm is idle
    tree_.halt();
    for (bt::NodeId id : subtrees_) tree_.remove(id, bt::Cut::Force);
    report.removed = subtrees_.size();
    subtrees_.clear();
    for (const plan::ActionTuple& t : tuples) subtrees_.push_back(tree_.append(root_, build_subtree(t, mode_, runner_)));
    report.inserted = tuples.size();
  } else {
    std::vector<std::string> old_actions, new_actions;
    for (const plan::ActionTuple& t : tuples_) old_actions.push_back(t.action);
    for (const plan::ActionTuple& t : tuples) new_actions.push_back(t.action);
    const std::vector<Edit> script = reconfiguration_script(old_actions, new_actions);
    // Dry run: would a removal cut a running, non-interruptible subtree?
    std::vector<bt::NodeId> ids = subtrees_;
    for (const Edit& e : script) {
      if (e.kind == Edit::Kind::Remove) {
        if (!tree_.can_cut(ids[e.position])) return report;  // defer the whole change
        ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(e.position));
      } else if (e.kind == Edit::Kind::Insert) {
        ids.insert(ids.begin() + static_cast<std::ptrdiff_t>(e.position), bt::kNoId);
      }
    }
    for (const Edit& e : script) {
      const auto pos = static_cast<std::ptrdiff_t>(e.position);
      switch (e.kind) {
        case Edit::Kind::Update:
          update_subtree(tree_.at(subtrees_[e.position]), tuples[e.plan_index], mode_, runner_);
          ++report.updated;
          break;
        case Edit::Kind::Insert:
          subtrees_.insert(subtrees_.begin() + pos,
                           tree_.insert(root_, e.position, build_subtree(tuples[e.plan_index], mode_, runner_)));
          ++report.inserted;
          break;
        case Edit::Kind::Remove:
          tree_.remove(subtrees_[e.position]);
          subtrees_.erase(subtrees_.begin() + pos);
          ++report.removed;
          break;
      }
    }
  }
  // With no move running, the new plan is executed from its first step (steps
  // already done succeed at once through their post-conditions).
  if (!any_running()) tree_.halt();
  tuples_ = tuples;
  changes_ += report.inserted + report.removed;
  report.applied = true;
  return report;
}

}  // namespace rtamp::exec
