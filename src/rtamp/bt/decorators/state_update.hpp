// rtamp::bt::StateUpdate — the paper's "State Update" decorator (Section III.D,
// Fig. 3a): after its child (an action) succeeds, it forces the current state on
// the blackboard to be updated. Generic: the update is a std::function hook.
//
// Ticks the child and returns its status unchanged; each tick in which the child
// returns SUCCESS, update(node) is called (before SUCCESS propagates up). The hook
// can be replaced in place. Exported as the custom decorator "StateUpdate" (its
// user ports, e.g. the effect it writes, become input ports in <TreeNodesModel>).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "rtamp/bt/decorator.hpp"

namespace rtamp::bt {

class StateUpdate : public Decorator {
 public:
  using Update = std::function<void(Node&)>;

  StateUpdate(std::string name, Update update, std::unique_ptr<Node> child = nullptr)
      : Decorator(std::move(name), std::move(child)), update_(std::move(update)) {}
  std::string_view type_id() const override { return "StateUpdate"; }
  void set_update(Update update) { update_ = std::move(update); }

 protected:
  Status on_tick() override {
    const Status s = tick_child();
    if (s == Status::Success && update_) update_(*this);
    return s;
  }

 private:
  Update update_;
};

}  // namespace rtamp::bt
