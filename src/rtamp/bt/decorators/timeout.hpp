// rtamp::bt::Timeout — fails its child if it runs too long (BehaviorTree.CPP
// `Timeout`, port msec), measured on the tree's injectable Clock (simulated time
// in the executor).
//
// A run starts when the Timeout is ticked while not RUNNING: the start time is
// taken and the child ticked. On later ticks of the same run, if at least
// `timeout` has elapsed the child is halted and Timeout returns FAILURE without
// ticking it; otherwise the child is ticked and its status returned.
#pragma once

#include <memory>
#include <string>

#include "rtamp/bt/decorator.hpp"

namespace rtamp::bt {

class Timeout : public Decorator {
 public:
  Timeout(std::string name, Duration timeout, std::unique_ptr<Node> child = nullptr);
  Timeout(Duration timeout, std::unique_ptr<Node> child) : Timeout("Timeout", timeout, std::move(child)) {}
  std::string_view type_id() const override { return "Timeout"; }
  bool btcpp_builtin() const override { return true; }
  Duration timeout() const { return timeout_; }
  // Exported as msec, rounded to the nearest millisecond.
  void collect_ports(std::vector<Port>& out) const override;

 protected:
  Status on_tick() override;

 private:
  Duration timeout_;
  Duration start_{};
};

}  // namespace rtamp::bt
