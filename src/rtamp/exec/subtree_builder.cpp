#include "rtamp/exec/subtree_builder.hpp"

namespace rtamp::exec {

const NameTable<ConditionMode>& condition_modes() {
  static const NameTable<ConditionMode> t = {
      {"action", ConditionMode::Action, "action conditions (Fig. 3b): a running move completes"},
      {"state", ConditionMode::State, "full-state conditions (Fig. 3a): any change preempts the move"},
  };
  return t;
}

const char* to_string(ConditionMode m) { return name_of(condition_modes(), m); }

bool holds(const std::vector<plan::Condition>& conditions, const world::Placement& placement) {
  for (const plan::Condition& c : conditions) {
    const std::string* loc = placement.location_of(c.thing);
    if (loc == nullptr || *loc != c.location) return false;
  }
  return true;
}

std::string to_string(const std::vector<plan::Condition>& conditions) {
  std::string out;
  for (const plan::Condition& c : conditions) {
    if (!out.empty()) out += " & ";
    out += c.thing + " in " + c.location;
  }
  return out.empty() ? "true" : out;
}

const std::vector<plan::Condition>& precondition(const plan::ActionTuple& t, ConditionMode mode) {
  return mode == ConditionMode::State ? t.pre : t.relaxed_pre;
}

namespace {

// The running condition C_R: the pre-state with the target in the hand (and,
// when the target is a container, its contents with it: they are not checked).
std::vector<plan::Condition> running_condition(const plan::ActionTuple& t) {
  std::vector<plan::Condition> out;
  for (const plan::Condition& c : t.pre) {
    if (c.thing == t.thing) out.push_back({c.thing, kInHand});
    else if (c.location != t.thing) out.push_back(c);
  }
  return out;
}

std::unique_ptr<bt::Condition> make_condition(const std::string& label, std::vector<plan::Condition> conds,
                                              const char* type_id) {
  auto node = std::make_unique<bt::Condition>(label, bt::Condition::Predicate{}, type_id);
  node->set_port("conditions", to_string(conds), "thing-in-location literals, all must hold");
  node->set_predicate([conds = std::move(conds)](bt::Node& self) {
    return holds(conds, self.blackboard().get<world::Placement>(kPlacementKey));
  });
  return node;
}

void set_condition(bt::Node& node, std::vector<plan::Condition> conds) {
  auto& cond = dynamic_cast<bt::Condition&>(node);
  cond.set_port("conditions", to_string(conds));
  cond.set_predicate([conds = std::move(conds)](bt::Node& self) {
    return holds(conds, self.blackboard().get<world::Placement>(kPlacementKey));
  });
}

bt::Action::Callbacks move_callbacks(const plan::ActionTuple& t, ActionRunner& runner) {
  auto tuple = std::make_shared<const plan::ActionTuple>(t);
  return bt::Action::Callbacks{
      [tuple, &runner](bt::Node&) { return runner.start(*tuple); },
      [tuple, &runner](bt::Node&) { return runner.running(*tuple); },
      [tuple, &runner](bt::Node&) { runner.halt(*tuple); }};
}

std::unique_ptr<bt::Action> make_move(const plan::ActionTuple& t, ActionRunner& runner) {
  auto move = std::make_unique<bt::Action>("Move " + t.thing + " -> " + t.to, move_callbacks(t, runner), "Move");
  move->set_port("object", t.thing, "the thing to pick");
  move->set_port("to", t.to, "the location to place it in");
  move->set_interruptible(false);
  return move;
}

void update_move(bt::Node& node, const plan::ActionTuple& t, ActionRunner& runner) {
  auto& move = dynamic_cast<bt::Action&>(node);
  move.set_callbacks(move_callbacks(t, runner));
  move.set_port("object", t.thing);
  move.set_port("to", t.to);
}

// The State Update decorator's effect: write the post-state into the believed placement.
bt::StateUpdate::Update state_update_hook(std::vector<plan::Condition> post) {
  return [post = std::move(post)](bt::Node& self) {
    auto& placement = self.blackboard().get<world::Placement>(kPlacementKey);
    for (const plan::Condition& c : post)
      if (auto it = placement.things.find(c.thing); it != placement.things.end()) it->second.location = c.location;
  };
}

}  // namespace

std::unique_ptr<bt::Node> build_subtree(const plan::ActionTuple& t, ConditionMode mode, ActionRunner& runner) {
  if (mode == ConditionMode::Action) {
    auto root = std::make_unique<bt::Chooser>(t.action);
    root->add(make_condition("post: " + to_string(t.relaxed_post), t.relaxed_post, "ActionCondition"));
    auto& seq = root->emplace<bt::Sequence>("do " + t.action);
    seq.add(make_condition("pre: " + to_string(t.relaxed_pre), t.relaxed_pre, "ActionCondition"));
    seq.add(make_move(t, runner));
    return root;
  }
  auto root = std::make_unique<bt::ReactiveFallback>(t.action);
  root->add(make_condition("post (state)", t.post, "StateCondition"));
  auto& seq = root->emplace<bt::ReactiveSequence>("do " + t.action);
  auto& enable = seq.emplace<bt::Fallback>("enabled");
  enable.add(make_condition("pre (state)", t.pre, "StateCondition"));
  enable.add(make_condition("running C_R", running_condition(t), "StateCondition"));
  auto update = std::make_unique<bt::StateUpdate>("state update", state_update_hook(t.post), make_move(t, runner));
  update->set_port("effect", to_string(t.post), "the state written after the move succeeds");
  seq.add(std::move(update));
  return root;
}

void update_subtree(bt::Node& subtree, const plan::ActionTuple& t, ConditionMode mode, ActionRunner& runner) {
  if (mode == ConditionMode::Action) {
    set_condition(subtree.child(0), t.relaxed_post);
    subtree.child(0).set_name("post: " + to_string(t.relaxed_post));
    bt::Node& seq = subtree.child(1);
    set_condition(seq.child(0), t.relaxed_pre);
    seq.child(0).set_name("pre: " + to_string(t.relaxed_pre));
    update_move(seq.child(1), t, runner);
    return;
  }
  set_condition(subtree.child(0), t.post);
  bt::Node& seq = subtree.child(1);
  set_condition(seq.child(0).child(0), t.pre);
  set_condition(seq.child(0).child(1), running_condition(t));
  auto& update = dynamic_cast<bt::StateUpdate&>(seq.child(1));
  update.set_update(state_update_hook(t.post));
  update.set_port("effect", to_string(t.post));
  update_move(update.child(0), t, runner);
}

}  // namespace rtamp::exec
