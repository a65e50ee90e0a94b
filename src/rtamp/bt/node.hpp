// rtamp::bt::Node — the base of every behavior-tree node (paper Section III.D:
// the tick travels from the root to the children; a node answers SUCCESS,
// RUNNING or FAILURE; INVALID until ticked or after a halt).
//
// Semantics follow py_trees / BehaviorTree.CPP:
//  - tick() runs the node's on_tick() and records the returned status; a node
//    must never return INVALID from on_tick() (tick() throws rtamp::Error);
//  - halt() stops a node: a RUNNING node is preempted (actions get on_halted,
//    composites halt their running children) and every halted node — running or
//    finished — returns to INVALID. Halting an INVALID node does nothing;
//  - a node knows whether it starts a new run from its own previous status
//    (status() != RUNNING when ticked => new run).
//
// Invariants kept by the engine:
//  - after a composite's tick, each of its children is either ticked in this run
//    or INVALID; a RUNNING child that is no longer ticked is halted;
//  - a node belongs to at most one parent and one tree; ids are 32-bit, issued by
//    the tree when the node is attached, never reused within that tree, and
//    unchanged by insertions, removals and replacements elsewhere;
//  - tick() does not allocate: children live in a ChildList, the status change is
//    reported to observers only when some are registered (one branch otherwise).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/bt/child_list.hpp"
#include "rtamp/bt/clock.hpp"
#include "rtamp/bt/status.hpp"

namespace rtamp::bt {

class Blackboard;
class Tree;

using NodeId = std::uint32_t;
inline constexpr NodeId kNoId = 0;  // a node that is not (yet) part of a tree

// What a node is, in BehaviorTree.CPP's terms (the <TreeNodesModel> element name).
enum class NodeKind : std::uint8_t { Action, Condition, Control, Decorator };
std::string_view to_string(NodeKind kind);

// A node parameter, exported as an XML attribute / BehaviorTree.CPP input port.
struct Port {
  std::string name;
  std::string value;
  std::string description;
};

// Per-tree state that nodes read on the hot path (owned by the Tree).
struct TreeContext {
  Tree* tree = nullptr;
  Blackboard* blackboard = nullptr;
  const Clock* clock = nullptr;
  std::uint64_t tick = 0;  // number of the current (or last) Tree::tick, 1-based
  bool observed = false;   // some status observer is registered
};

// Throws rtamp::Error unless `id` is a valid BehaviorTree.CPP node ID for a custom
// node: [A-Za-z][A-Za-z0-9_]*, and not the name of a BehaviorTree.CPP built-in.
void validate_type_id(std::string_view id);

class Node {
  // Hot fields first, next to the vtable pointer, so a tick touches one cache line.
  Status status_ = Status::Invalid;
  bool interruptible_ = true;
  NodeId id_ = kNoId;
  TreeContext* ctx_ = nullptr;

 protected:
  ChildList children_;  // owned: deleted by ~Node

 public:
  explicit Node(std::string name);
  virtual ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  // ---- execution -------------------------------------------------------
  Status tick() {
    const Status s = on_tick();
    if (s == Status::Invalid) [[unlikely]]
      throw_invalid_status();
    if (s != status_) set_status(s);
    return s;
  }
  void halt() {
    if (status_ != Status::Invalid) halt_now();
  }
  Status status() const { return status_; }

  // ---- identity ----------------------------------------------------------
  NodeId id() const { return id_; }
  const std::string& name() const { return name_; }
  void set_name(std::string name) { name_ = std::move(name); }
  virtual NodeKind kind() const = 0;
  // The BehaviorTree.CPP registration ID: "Sequence", "Chooser", or a user leaf's ID.
  virtual std::string_view type_id() const = 0;
  // True for node types BehaviorTree.CPP 4 provides (they need no <TreeNodesModel> entry).
  virtual bool btcpp_builtin() const { return false; }

  // ---- structure -----------------------------------------------------------
  std::span<Node* const> children() const { return children_.span(); }
  std::size_t child_count() const { return children_.size(); }
  // Child i; throws std::out_of_range if there is none.
  Node& child(std::size_t i) const;
  Node* parent() const { return parent_; }
  // Position among the parent's children (0 for a root or detached node).
  std::size_t index_in_parent() const;

  // A non-interruptible node must not be cut out of the tree while it runs: Tree's
  // remove/replace refuse (unless forced) when such a node is RUNNING in the subtree.
  bool interruptible() const { return interruptible_; }
  void set_interruptible(bool value) { interruptible_ = value; }

  // ---- parameters (exported as ports) ---------------------------------------
  // User ports (custom nodes: leaves, Chooser, StateUpdate). Setting an existing
  // name replaces its value — how Algorithm 2 updates a condition in place.
  void set_port(std::string name, std::string value, std::string description = {});
  const std::vector<Port>& user_ports() const { return ports_; }
  // The value of a user port, or nullptr.
  const std::string* port(std::string_view name) const;
  // Every port to export: built-in parameters (e.g. Parallel's success_count), then
  // user ports of custom nodes.
  virtual void collect_ports(std::vector<Port>& out) const;

  // ---- context -------------------------------------------------------------
  bool attached() const { return ctx_ != nullptr; }
  Tree* tree() const { return ctx_ != nullptr ? ctx_->tree : nullptr; }
  // The tree's blackboard / clock time / tick number. Throw rtamp::Error if detached.
  Blackboard& blackboard() const;
  Duration now() const;
  std::uint64_t tick_count() const;

 protected:
  // The node's behaviour for one tick. Never returns Status::Invalid.
  virtual Status on_tick() = 0;
  // Called by halt() while status() is still the pre-halt status (not INVALID).
  // Leaves stop their work if RUNNING; composites/decorators halt their children
  // and reset their own bookkeeping.
  virtual void on_halt() {}

  // Child management for Composite and Decorator. A child must be detached
  // (no parent, no tree); it is halted to INVALID first if needed. When this node
  // is in a tree, the new nodes are registered (ids issued) and removed ones
  // unregistered; removed children are halted first.
  Node& insert_child_impl(std::size_t pos, std::unique_ptr<Node> child);
  std::unique_ptr<Node> take_child_impl(std::size_t pos);
  std::unique_ptr<Node> swap_child_impl(std::size_t pos, std::unique_ptr<Node> child);

 private:
  friend class Tree;

  void set_status(Status s);
  void halt_now();
  [[noreturn]] void throw_invalid_status() const;

  std::string name_;
  std::vector<Port> ports_;
  Node* parent_ = nullptr;
  std::uint64_t id_owner_ = 0;  // serial of the tree that issued id_
};

}  // namespace rtamp::bt
