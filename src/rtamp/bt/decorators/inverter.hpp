// rtamp::bt::Inverter — swaps SUCCESS and FAILURE of its child; RUNNING passes
// through (BehaviorTree.CPP `Inverter`, py_trees `Inverter`).
#pragma once

#include <memory>
#include <string>

#include "rtamp/bt/decorator.hpp"

namespace rtamp::bt {

class Inverter : public Decorator {
 public:
  explicit Inverter(std::string name = "Inverter", std::unique_ptr<Node> child = nullptr)
      : Decorator(std::move(name), std::move(child)) {}
  explicit Inverter(std::unique_ptr<Node> child) : Inverter("Inverter", std::move(child)) {}
  std::string_view type_id() const override { return "Inverter"; }
  bool btcpp_builtin() const override { return true; }

 protected:
  Status on_tick() override {
    switch (tick_child()) {
      case Status::Success:
        return Status::Failure;
      case Status::Failure:
        return Status::Success;
      default:
        return Status::Running;
    }
  }
};

}  // namespace rtamp::bt
