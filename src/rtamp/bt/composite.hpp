// rtamp::bt::Composite — base of the control nodes (Sequence, Fallback, their
// reactive forms, Chooser, Parallel): an ordered list of children and the
// bookkeeping that keeps "every child is ticked in this run or INVALID" cheap.
//
// Invariants:
//  - children at index >= touched_ are INVALID (touched_ is one past the highest
//    child ticked since the children were last reset), so resetting the tail
//    after a decision costs only what was actually touched;
//  - insert/remove/replace keep touched_ and the subclass's position (running
//    child index) pointing at the same children (hooks child_inserted/removed/
//    replaced), so a change before a running child does not disturb it.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "rtamp/bt/node.hpp"

namespace rtamp::bt {

class Composite : public Node {
 public:
  using Node::Node;
  NodeKind kind() const final { return NodeKind::Control; }

  // Appends a child (building a tree); returns *this for chaining.
  Composite& add(std::unique_ptr<Node> child) {
    insert_child(child_count(), std::move(child));
    return *this;
  }
  // Creates a child in place and returns it.
  template <class T, class... Args>
  T& emplace(Args&&... args) {
    auto node = std::make_unique<T>(std::forward<Args>(args)...);
    T& ref = *node;
    insert_child(child_count(), std::move(node));
    return ref;
  }
  // Low-level structural edits (Tree::insert/remove/replace call these and add the
  // interruptibility check and change notifications; prefer those on a live tree).
  Node& insert_child(std::size_t pos, std::unique_ptr<Node> child);
  std::unique_ptr<Node> remove_child(std::size_t pos);
  std::unique_ptr<Node> replace_child(std::size_t pos, std::unique_ptr<Node> child);

 protected:
  // Records that child i was ticked in the current run.
  void note_ticked(std::size_t i) {
    if (i >= touched_) touched_ = i + 1;
  }
  // Halts children [first, touched_) that are not INVALID; touched_ <= first after.
  void reset_from(std::size_t first);
  // Halts every child and calls on_reset().
  void on_halt() override;
  // The subclass forgets its run state (running child index, ...).
  virtual void on_reset() {}
  virtual void child_inserted(std::size_t /*pos*/) {}
  virtual void child_removed(std::size_t /*pos*/) {}
  virtual void child_replaced(std::size_t /*pos*/) {}

  std::size_t touched_ = 0;
};

}  // namespace rtamp::bt
