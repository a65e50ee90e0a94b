// rtamp::bt::Action — a leaf that does something, possibly over many ticks (like
// BehaviorTree.CPP's StatefulActionNode): on_start() when ticked while not
// RUNNING, on_running() on later ticks while it runs, on_halted() when it is
// halted while RUNNING (preempted by a reactive parent, cut out of the tree, or
// the tree halted). Each returns SUCCESS, RUNNING or FAILURE (never INVALID).
// Built from callables taking the node (reach the blackboard/clock through it),
// or by subclassing and overriding the three hooks.
//
// A finished action ticked again starts again (on_start). Actions are
// interruptible by default; set_interruptible(false) makes Tree::remove/replace
// refuse to cut it while it runs (Algorithm 2 then defers the change).
// Exported as <TYPE_ID .../> with TYPE_ID in <TreeNodesModel> as an <Action>.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

#include "rtamp/bt/node.hpp"

namespace rtamp::bt {

class Action : public Node {
 public:
  using Tick = std::function<Status(Node&)>;
  using Halted = std::function<void(Node&)>;
  struct Callbacks {
    Tick on_start;     // required
    Tick on_running;   // if empty, on_start is called on every tick
    Halted on_halted;  // optional
  };

  Action(std::string name, Callbacks callbacks, std::string type_id = "UserAction");
  // One function for every tick (a synchronous action if it never returns RUNNING).
  Action(std::string name, Tick tick, std::string type_id = "UserAction")
      : Action(std::move(name), Callbacks{std::move(tick), {}, {}}, std::move(type_id)) {}
  template <class F>
  requires(std::is_invocable_r_v<Status, F&> && !std::is_invocable_v<F&, Node&>)
      Action(std::string name, F tick, std::string type_id = "UserAction")
      : Action(std::move(name), Tick([f = std::move(tick)](Node&) mutable { return f(); }),
               std::move(type_id)) {}

  NodeKind kind() const override { return NodeKind::Action; }
  std::string_view type_id() const override { return type_id_; }
  void set_callbacks(Callbacks callbacks) { callbacks_ = std::move(callbacks); }

 protected:
  // For subclasses that override the hooks.
  Action(std::string name, std::string type_id);
  virtual Status on_start();
  virtual Status on_running();
  virtual void on_halted();

  Status on_tick() final { return status() == Status::Running ? on_running() : on_start(); }
  void on_halt() final {
    if (status() == Status::Running) on_halted();
  }

 private:
  Callbacks callbacks_;
  std::string type_id_;
};

}  // namespace rtamp::bt
