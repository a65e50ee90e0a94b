#include "rtamp/bt/node.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <stdexcept>

#include "rtamp/bt/tree.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::bt {

std::string_view to_string(NodeKind kind) {
  switch (kind) {
    case NodeKind::Action:
      return "Action";
    case NodeKind::Condition:
      return "Condition";
    case NodeKind::Control:
      return "Control";
    case NodeKind::Decorator:
      return "Decorator";
  }
  return "?";
}

namespace {
// Registration IDs BehaviorTree.CPP 4 provides or reserves; a custom node may not reuse them.
constexpr std::array<std::string_view, 52> kBtcppReserved = {"Action",
                                                             "Condition",
                                                             "Control",
                                                             "Decorator",
                                                             "SubTree",
                                                             "BehaviorTree",
                                                             "TreeNodesModel",
                                                             "root",
                                                             "Root",
                                                             "include",
                                                             "Sequence",
                                                             "SequenceWithMemory",
                                                             "SequenceStar",
                                                             "ReactiveSequence",
                                                             "Fallback",
                                                             "FallbackWithMemory",
                                                             "ReactiveFallback",
                                                             "Parallel",
                                                             "ParallelAll",
                                                             "IfThenElse",
                                                             "WhileDoElse",
                                                             "Switch2",
                                                             "Switch3",
                                                             "Switch4",
                                                             "Switch5",
                                                             "Switch6",
                                                             "ManualSelector",
                                                             "TryCatch",
                                                             "Inverter",
                                                             "RetryUntilSuccessful",
                                                             "KeepRunningUntilFailure",
                                                             "Repeat",
                                                             "Timeout",
                                                             "Delay",
                                                             "ForceSuccess",
                                                             "ForceFailure",
                                                             "RunOnce",
                                                             "Precondition",
                                                             "SkipUnlessUpdated",
                                                             "WaitValueUpdate",
                                                             "LoopInt",
                                                             "LoopDouble",
                                                             "LoopString",
                                                             "LoopBool",
                                                             "AlwaysSuccess",
                                                             "AlwaysFailure",
                                                             "SetBlackboard",
                                                             "UnsetBlackboard",
                                                             "Sleep",
                                                             "Script",
                                                             "ScriptCondition",
                                                             "WasEntryUpdated"};
}  // namespace

void validate_type_id(std::string_view id) {
  bool ok = !id.empty() && std::isalpha(static_cast<unsigned char>(id.front())) != 0;
  for (char c : id) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_');
  if (!ok) {
    throw rtamp::Error("behavior-tree node type ID '" + std::string(id) +
                       "' is not a valid BehaviorTree.CPP ID (letters, digits, '_', starting with a letter)");
  }
  if (std::find(kBtcppReserved.begin(), kBtcppReserved.end(), id) != kBtcppReserved.end()) {
    throw rtamp::Error("behavior-tree node type ID '" + std::string(id) +
                       "' is reserved by BehaviorTree.CPP; choose another ID for a custom node");
  }
}

Node::Node(std::string name) : name_(std::move(name)) {}
Node::~Node() {
  for (Node* c : children_) delete c;
}

Node& Node::child(std::size_t i) const {
  if (i >= children_.size()) {
    throw std::out_of_range("behavior-tree node '" + name_ + "' has no child " + std::to_string(i));
  }
  return *children_[i];
}

std::size_t Node::index_in_parent() const {
  if (parent_ == nullptr) return 0;
  const auto& siblings = parent_->children_;
  for (std::size_t i = 0; i < siblings.size(); ++i) {
    if (siblings[i] == this) return i;
  }
  return 0;  // unreachable: a parent always holds its child
}

void Node::set_port(std::string name, std::string value, std::string description) {
  bool ok = !name.empty() && std::isalpha(static_cast<unsigned char>(name.front())) != 0;
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_');
  if (!ok || name == "name" || name == "ID") {
    throw rtamp::Error(
        "behavior-tree node '" + name_ + "': '" + name +
        "' is not a usable port name (letters, digits, '_', starting with a letter; not name/ID)");
  }
  for (Port& p : ports_) {
    if (p.name == name) {
      p.value = std::move(value);
      if (!description.empty()) p.description = std::move(description);
      return;
    }
  }
  ports_.push_back(Port{std::move(name), std::move(value), std::move(description)});
}

const std::string* Node::port(std::string_view name) const {
  for (const Port& p : ports_) {
    if (p.name == name) return &p.value;
  }
  return nullptr;
}

void Node::collect_ports(std::vector<Port>& out) const {
  if (!btcpp_builtin()) out.insert(out.end(), ports_.begin(), ports_.end());
}

Blackboard& Node::blackboard() const {
  if (ctx_ == nullptr)
    throw rtamp::Error("behavior-tree node '" + name_ + "' is not in a tree: no blackboard");
  return *ctx_->blackboard;
}

Duration Node::now() const {
  if (ctx_ == nullptr) throw rtamp::Error("behavior-tree node '" + name_ + "' is not in a tree: no clock");
  return ctx_->clock->now();
}

std::uint64_t Node::tick_count() const { return ctx_ != nullptr ? ctx_->tick : 0; }

void Node::set_status(Status s) {
  const Status previous = status_;
  status_ = s;
  if (ctx_ != nullptr && ctx_->observed) ctx_->tree->notify_status(*this, previous, s);
}

void Node::halt_now() {
  on_halt();
  set_status(Status::Invalid);
}

void Node::throw_invalid_status() const {
  throw rtamp::Error("behavior-tree node '" + name_ + "' (" + std::string(type_id()) +
                     ") returned INVALID from tick; a tick must return SUCCESS, RUNNING or FAILURE");
}

Node& Node::insert_child_impl(std::size_t pos, std::unique_ptr<Node> child) {
  if (!child) throw rtamp::Error("behavior tree: cannot add a null child to '" + name_ + "'");
  if (child->parent_ != nullptr || child->ctx_ != nullptr) {
    throw rtamp::Error("behavior tree: node '" + child->name_ + "' already has a parent or a tree");
  }
  if (pos > children_.size()) {
    throw rtamp::Error("behavior tree: position " + std::to_string(pos) + " out of range under '" + name_ +
                       "' (" + std::to_string(children_.size()) + " children)");
  }
  child->halt();  // a detached subtree enters INVALID (no observers: it is detached)
  Node& ref = *child;
  child->parent_ = this;
  children_.insert(pos, child.get());  // may grow (throw) while `child` still owns the node
  child.release();
  if (ctx_ != nullptr) ctx_->tree->adopt(ref);
  return ref;
}

std::unique_ptr<Node> Node::take_child_impl(std::size_t pos) {
  if (pos >= children_.size()) {
    throw rtamp::Error("behavior tree: no child " + std::to_string(pos) + " under '" + name_ + "'");
  }
  Node& child = *children_[pos];
  child.halt();
  if (ctx_ != nullptr) ctx_->tree->release(child);
  child.parent_ = nullptr;
  std::unique_ptr<Node> out(children_[pos]);
  children_.erase(pos);
  return out;
}

std::unique_ptr<Node> Node::swap_child_impl(std::size_t pos, std::unique_ptr<Node> child) {
  if (!child) throw rtamp::Error("behavior tree: cannot put a null child under '" + name_ + "'");
  if (child->parent_ != nullptr || child->ctx_ != nullptr) {
    throw rtamp::Error("behavior tree: node '" + child->name_ + "' already has a parent or a tree");
  }
  if (pos >= children_.size()) {
    throw rtamp::Error("behavior tree: no child " + std::to_string(pos) + " under '" + name_ + "'");
  }
  Node& old = *children_[pos];
  old.halt();
  if (ctx_ != nullptr) ctx_->tree->release(old);
  old.parent_ = nullptr;
  child->halt();
  child->parent_ = this;
  std::unique_ptr<Node> out(children_.exchange(pos, child.release()));
  if (ctx_ != nullptr) ctx_->tree->adopt(*children_[pos]);
  return out;
}

}  // namespace rtamp::bt
