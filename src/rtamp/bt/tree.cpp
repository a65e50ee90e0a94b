#include "rtamp/bt/tree.hpp"

#include <atomic>
#include <limits>

#include "rtamp/bt/composite.hpp"
#include "rtamp/bt/decorator.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::bt {

std::string_view to_string(TreeChange::Kind kind) {
  switch (kind) {
    case TreeChange::Kind::SetRoot:
      return "set_root";
    case TreeChange::Kind::Insert:
      return "insert";
    case TreeChange::Kind::Remove:
      return "remove";
    case TreeChange::Kind::Replace:
      return "replace";
  }
  return "?";
}

void accept(const Node& root, Visitor& visitor, int depth) {
  if (visitor.enter(root, depth)) {
    for (const auto& c : root.children()) accept(*c, visitor, depth + 1);
  }
  visitor.leave(root, depth);
}

namespace {
std::atomic<std::uint64_t> g_tree_serial{1};

// True if some RUNNING, non-interruptible node is in the subtree (only running
// branches are walked: a node that is not RUNNING has no running descendants).
bool has_running_uninterruptible(const Node& node) {
  if (node.status() != Status::Running) return false;
  if (!node.interruptible()) return true;
  for (const auto& c : node.children()) {
    if (has_running_uninterruptible(*c)) return true;
  }
  return false;
}
}  // namespace

Tree::Tree(std::shared_ptr<Blackboard> blackboard, std::shared_ptr<const Clock> clock)
    : ctx_(std::make_unique<TreeContext>()),
      blackboard_(blackboard ? std::move(blackboard) : std::make_shared<Blackboard>()),
      clock_(clock ? std::move(clock) : std::make_shared<SteadyClock>()),
      serial_(g_tree_serial.fetch_add(1)) {
  ctx_->tree = this;
  ctx_->blackboard = blackboard_.get();
  ctx_->clock = clock_.get();
}

Tree::~Tree() {
  // Running actions are halted (their on_halted runs: a robot must not keep moving
  // for a tree that is gone); observers are not told any more.
  status_observers_.clear();
  change_observers_.clear();
  ctx_->observed = false;
  if (root_) {
    try {
      root_->halt();
    } catch (...) {  // a destructor must not throw; the nodes are going away anyway
    }
  }
}

void Tree::set_clock(std::shared_ptr<const Clock> clock) {
  if (!clock) throw rtamp::Error("behavior tree: null clock");
  clock_ = std::move(clock);
  ctx_->clock = clock_.get();
}

NodeId Tree::set_root(std::unique_ptr<Node> root) {
  if (root && (root->parent_ != nullptr || root->ctx_ != nullptr)) {
    throw rtamp::Error("behavior tree: node '" + root->name() + "' already has a parent or a tree");
  }
  NodeId previous = kNoId;
  if (root_) {
    previous = root_->id();
    root_->halt();
    release(*root_);
    root_.reset();
  }
  NodeId id = kNoId;
  if (root) {
    root->halt();
    root_ = std::move(root);
    adopt(*root_);
    id = root_->id();
  }
  ++change_count_;
  notify_change(TreeChange{TreeChange::Kind::SetRoot, id, previous, kNoId, 0, ctx_->tick});
  return id;
}

Node* Tree::find(NodeId id) const {
  auto it = index_.find(id);
  return it == index_.end() ? nullptr : it->second;
}

Node& Tree::at(NodeId id) const {
  Node* n = find(id);
  if (n == nullptr) throw rtamp::Error("behavior tree has no node with id " + std::to_string(id));
  return *n;
}

Node* Tree::find_by_name(std::string_view name) const {
  Node* found = nullptr;
  struct V : Visitor {
    std::string_view name;
    Node** found;
    bool enter(const Node& n, int) override {
      if (*found != nullptr) return false;
      if (n.name() == name) *found = const_cast<Node*>(&n);
      return *found == nullptr;
    }
  } v;
  v.name = name;
  v.found = &found;
  if (root_) bt::accept(*root_, v);
  return found;
}

NodeId Tree::insert(NodeId parent, std::size_t position, std::unique_ptr<Node> subtree) {
  auto* composite = dynamic_cast<Composite*>(&at(parent));
  if (composite == nullptr) {
    throw rtamp::Error("behavior tree: cannot insert under '" + at(parent).name() +
                       "': it is not a composite (use replace for a decorator's child)");
  }
  Node& node = composite->insert_child(position, std::move(subtree));
  ++change_count_;
  notify_change(TreeChange{TreeChange::Kind::Insert, node.id(), kNoId, parent, position, ctx_->tick});
  return node.id();
}

NodeId Tree::append(NodeId parent, std::unique_ptr<Node> subtree) {
  return insert(parent, at(parent).child_count(), std::move(subtree));
}

bool Tree::can_cut(NodeId id) const { return !has_running_uninterruptible(at(id)); }

void Tree::check_cut(NodeId id, Cut cut, const char* what) const {
  if (cut == Cut::IfInterruptible && !can_cut(id)) {
    throw rtamp::Error(std::string("behavior tree: cannot ") + what + " '" + at(id).name() + "' (id " +
                       std::to_string(id) + "): it contains a running non-interruptible node");
  }
}

std::unique_ptr<Node> Tree::remove(NodeId id, Cut cut) {
  Node& node = at(id);
  check_cut(id, cut, "remove");
  Node* parent = node.parent();
  std::unique_ptr<Node> out;
  std::size_t position = 0;
  NodeId parent_id = kNoId;
  if (parent == nullptr) {
    root_->halt();
    release(*root_);
    out = std::move(root_);
  } else {
    auto* composite = dynamic_cast<Composite*>(parent);
    if (composite == nullptr) {
      throw rtamp::Error("behavior tree: cannot remove '" + node.name() + "', the only child of decorator '" +
                         parent->name() + "'; replace it instead");
    }
    position = node.index_in_parent();
    parent_id = parent->id();
    out = composite->remove_child(position);
  }
  ++change_count_;
  notify_change(TreeChange{TreeChange::Kind::Remove, id, kNoId, parent_id, position, ctx_->tick});
  return out;
}

NodeId Tree::replace(NodeId id, std::unique_ptr<Node> subtree, Cut cut, std::unique_ptr<Node>* removed) {
  Node& node = at(id);
  if (!subtree) throw rtamp::Error("behavior tree: cannot replace '" + node.name() + "' with nothing");
  check_cut(id, cut, "replace");
  Node* parent = node.parent();
  std::unique_ptr<Node> old;
  std::size_t position = 0;
  NodeId parent_id = kNoId;
  NodeId new_id = kNoId;
  if (parent == nullptr) {
    if (subtree->parent_ != nullptr || subtree->ctx_ != nullptr) {
      throw rtamp::Error("behavior tree: node '" + subtree->name() + "' already has a parent or a tree");
    }
    root_->halt();
    release(*root_);
    old = std::move(root_);
    subtree->halt();
    root_ = std::move(subtree);
    adopt(*root_);
    new_id = root_->id();
  } else {
    position = node.index_in_parent();
    parent_id = parent->id();
    Node* fresh = subtree.get();
    if (auto* composite = dynamic_cast<Composite*>(parent)) {
      old = composite->replace_child(position, std::move(subtree));
    } else if (auto* decorator = dynamic_cast<Decorator*>(parent)) {
      old = decorator->set_child(std::move(subtree));
    } else {
      throw rtamp::Error("behavior tree: parent '" + parent->name() + "' cannot hold children");
    }
    new_id = fresh->id();
  }
  ++change_count_;
  notify_change(TreeChange{TreeChange::Kind::Replace, new_id, id, parent_id, position, ctx_->tick});
  if (removed != nullptr) *removed = std::move(old);
  return new_id;
}

Status Tree::tick() {
  ++ctx_->tick;
  if (!root_) return Status::Invalid;
  return root_->tick();
}

void Tree::halt() {
  if (root_) root_->halt();
}

Tree::ObserverHandle Tree::add_status_observer(StatusObserver observer) {
  if (!observer) throw rtamp::Error("behavior tree: empty status observer");
  const ObserverHandle h = next_handle_++;
  status_observers_.emplace_back(h, std::move(observer));
  ctx_->observed = true;
  return h;
}

Tree::ObserverHandle Tree::add_change_observer(ChangeObserver observer) {
  if (!observer) throw rtamp::Error("behavior tree: empty change observer");
  const ObserverHandle h = next_handle_++;
  change_observers_.emplace_back(h, std::move(observer));
  return h;
}

bool Tree::remove_observer(ObserverHandle handle) {
  for (auto it = status_observers_.begin(); it != status_observers_.end(); ++it) {
    if (it->first == handle) {
      status_observers_.erase(it);
      ctx_->observed = !status_observers_.empty();
      return true;
    }
  }
  for (auto it = change_observers_.begin(); it != change_observers_.end(); ++it) {
    if (it->first == handle) {
      change_observers_.erase(it);
      return true;
    }
  }
  return false;
}

void Tree::accept(Visitor& visitor) const {
  if (root_) bt::accept(*root_, visitor);
}

void Tree::for_each(const std::function<void(const Node&, int)>& fn) const {
  struct V : Visitor {
    const std::function<void(const Node&, int)>* fn;
    bool enter(const Node& n, int depth) override {
      (*fn)(n, depth);
      return true;
    }
  } v;
  v.fn = &fn;
  accept(v);
}

void Tree::adopt(Node& node) {
  node.ctx_ = ctx_.get();
  const bool keep = node.id_ != kNoId && node.id_owner_ == serial_ && index_.find(node.id_) == index_.end();
  if (!keep) {
    if (next_id_ == std::numeric_limits<NodeId>::max()) {
      throw rtamp::Error("behavior tree: 32-bit node ids exhausted");
    }
    node.id_ = next_id_++;
    node.id_owner_ = serial_;
  }
  index_.emplace(node.id_, &node);
  for (auto& c : node.children_) adopt(*c);
}

void Tree::release(Node& node) {
  for (auto& c : node.children_) release(*c);
  index_.erase(node.id_);
  node.ctx_ = nullptr;
}

void Tree::notify_status(const Node& node, Status previous, Status current) {
  const StatusChange change{node, node.id(), node.name(), previous, current, ctx_->tick};
  for (auto& [h, fn] : status_observers_) fn(change);
}

void Tree::notify_change(const TreeChange& change) {
  for (auto& [h, fn] : change_observers_) fn(change);
}

}  // namespace rtamp::bt
