// rtamp::bt::Decorator — base of the one-child nodes (Inverter, Retry, Timeout,
// StateUpdate). Invariant: a decorator in a tree that is ticked has a child
// (ticking one without a child throws rtamp::Error).
#pragma once

#include <memory>
#include <string>

#include "rtamp/bt/node.hpp"

namespace rtamp::bt {

class Decorator : public Node {
 public:
  explicit Decorator(std::string name, std::unique_ptr<Node> child = nullptr);
  NodeKind kind() const final { return NodeKind::Decorator; }

  Node* child_node() const { return children_.empty() ? nullptr : children_[0]; }
  // Sets the child; the previous one (halted, detached) is returned.
  std::unique_ptr<Node> set_child(std::unique_ptr<Node> child);

 protected:
  Status tick_child() {
    if (children_.empty()) [[unlikely]]
      throw_no_child();
    return children_[0]->tick();
  }
  void halt_child() {
    if (!children_.empty()) children_[0]->halt();
  }
  // Halts the child and calls on_reset().
  void on_halt() override;
  virtual void on_reset() {}

 private:
  [[noreturn]] void throw_no_child() const;
};

}  // namespace rtamp::bt
