// rtamp::bt::Tree — a behavior tree: the root node, the blackboard and clock
// its nodes share, the id registry, observers, and the change API that lets
// the tree be reconfigured between ticks (paper Section III.D, Algorithm 2:
// keep shared subtrees, update their conditions in place, add and remove the
// rest, never cut a running non-interruptible subtree).
//
// Invariants:
//  - every node reachable from the root is registered under its id; ids are
//    32-bit, issued in increasing order, never reused within a tree (a removed
//    subtree that is inserted again into the same tree keeps its ids: a move);
//  - insert/remove/replace touch only the named position: other nodes keep their
//    status and running state (a running action elsewhere keeps running; a
//    Sequence with memory keeps its running child when a sibling is inserted or
//    removed before it); removed/replaced subtrees are halted (running nodes get
//    their halt callbacks) before they leave the tree;
//  - changes are made between ticks, from the thread that ticks (not thread-safe);
//  - tick() allocates nothing by itself (observers and user callables may).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "rtamp/bt/blackboard.hpp"
#include "rtamp/bt/clock.hpp"
#include "rtamp/bt/node.hpp"

namespace rtamp::bt {

// One status transition of one node, reported to status observers.
struct StatusChange {
  const Node& node;
  NodeId id;
  std::string_view name;
  Status previous;
  Status current;
  std::uint64_t tick;  // Tree::tick_count() when it happened (changes between ticks: the last tick)
};

// One structural change, reported to change observers.
struct TreeChange {
  enum class Kind : std::uint8_t { SetRoot, Insert, Remove, Replace };
  Kind kind;
  NodeId node;           // the inserted / removed / new subtree root
  NodeId previous;       // Replace, SetRoot: the subtree root that left; otherwise kNoId
  NodeId parent;         // kNoId for the root
  std::size_t position;  // index under the parent
  std::uint64_t tick;
};
std::string_view to_string(TreeChange::Kind kind);

// Whether a change may cut a running non-interruptible subtree.
enum class Cut : std::uint8_t {
  IfInterruptible,  // refuse (throw rtamp::Error) if can_cut() is false — the default
  Force,            // halt whatever runs
};

// Depth-first visitor: enter() before the children (return false to skip them),
// leave() after them.
class Visitor {
 public:
  virtual ~Visitor() = default;
  virtual bool enter(const Node& node, int depth) = 0;
  virtual void leave(const Node& /*node*/, int /*depth*/) {}
};
void accept(const Node& root, Visitor& visitor, int depth = 0);

class Tree {
 public:
  using ObserverHandle = std::uint32_t;
  using StatusObserver = std::function<void(const StatusChange&)>;
  using ChangeObserver = std::function<void(const TreeChange&)>;

  explicit Tree(std::shared_ptr<Blackboard> blackboard = std::make_shared<Blackboard>(),
                std::shared_ptr<const Clock> clock = std::make_shared<SteadyClock>());
  // Halts the tree (running actions get on_halted; observers are not called).
  ~Tree();
  Tree(const Tree&) = delete;
  Tree& operator=(const Tree&) = delete;

  // ---- structure ------------------------------------------------------------
  Node* root() const { return root_.get(); }
  // Installs a new root (the old one, if any, is halted and dropped). Returns its id.
  NodeId set_root(std::unique_ptr<Node> root);
  // The node with this id, or nullptr.
  Node* find(NodeId id) const;
  // The node with this id; throws rtamp::Error if there is none.
  Node& at(NodeId id) const;
  // Number of nodes in the tree.
  std::size_t size() const { return index_.size(); }
  // First node (pre-order) with this name, or nullptr.
  Node* find_by_name(std::string_view name) const;

  // Inserts `subtree` as child number `position` (0..child_count) of the composite
  // `parent`. Returns the id of the subtree's root.
  NodeId insert(NodeId parent, std::size_t position, std::unique_ptr<Node> subtree);
  NodeId append(NodeId parent, std::unique_ptr<Node> subtree);
  // Removes the subtree rooted at `id` (a composite's child, or the root): halts its
  // running nodes, unregisters it and hands it back (discard it, or insert it again).
  std::unique_ptr<Node> remove(NodeId id, Cut cut = Cut::IfInterruptible);
  // Puts `subtree` where `id` is (composite child, decorator child or root); the old
  // subtree is halted, unregistered and returned through `removed` if given.
  NodeId replace(NodeId id, std::unique_ptr<Node> subtree, Cut cut = Cut::IfInterruptible,
                 std::unique_ptr<Node>* removed = nullptr);
  // False if some node in the subtree is RUNNING and not interruptible.
  bool can_cut(NodeId id) const;
  // Number of insert/remove/replace/set_root calls so far.
  std::uint64_t change_count() const { return change_count_; }

  // ---- execution --------------------------------------------------------------
  // Ticks the root once (tick_count() first goes up by one). INVALID if there is no root.
  Status tick();
  // Halts the whole tree (every node back to INVALID).
  void halt();
  Status status() const { return root_ ? root_->status() : Status::Invalid; }
  std::uint64_t tick_count() const { return ctx_->tick; }

  Blackboard& blackboard() const { return *blackboard_; }
  const std::shared_ptr<Blackboard>& shared_blackboard() const { return blackboard_; }
  const Clock& clock() const { return *clock_; }
  void set_clock(std::shared_ptr<const Clock> clock);

  // ---- observers ----------------------------------------------------------------
  ObserverHandle add_status_observer(StatusObserver observer);
  ObserverHandle add_change_observer(ChangeObserver observer);
  // Returns whether the handle was registered.
  bool remove_observer(ObserverHandle handle);

  // ---- visiting -------------------------------------------------------------------
  void accept(Visitor& visitor) const;
  // Pre-order over every node with its depth (root: 0).
  void for_each(const std::function<void(const Node&, int)>& fn) const;

 private:
  friend class Node;

  void adopt(Node& node);    // registers a subtree that was just attached
  void release(Node& node);  // unregisters a subtree that is leaving
  void notify_status(const Node& node, Status previous, Status current);
  void notify_change(const TreeChange& change);
  void check_cut(NodeId id, Cut cut, const char* what) const;

  std::unique_ptr<TreeContext> ctx_;
  std::shared_ptr<Blackboard> blackboard_;
  std::shared_ptr<const Clock> clock_;
  std::unique_ptr<Node> root_;
  std::unordered_map<NodeId, Node*> index_;
  std::uint64_t serial_;
  NodeId next_id_ = 1;
  std::uint64_t change_count_ = 0;
  ObserverHandle next_handle_ = 1;
  std::vector<std::pair<ObserverHandle, StatusObserver>> status_observers_;
  std::vector<std::pair<ObserverHandle, ChangeObserver>> change_observers_;
};

}  // namespace rtamp::bt
