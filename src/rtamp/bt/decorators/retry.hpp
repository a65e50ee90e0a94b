// rtamp::bt::Retry — gives its child up to n attempts (BehaviorTree.CPP
// `RetryUntilSuccessful`, port num_attempts; -1 = unlimited).
//
// SUCCESS of the child is SUCCESS (attempts are counted afresh in the next run);
// RUNNING is RUNNING. FAILURE of an attempt: if attempts remain, the child is
// reset and Retry returns RUNNING — the next attempt starts on the NEXT tick (so
// an always-failing child can never hang a tick, even with unlimited attempts);
// after the n-th failed attempt Retry returns FAILURE. (Older BehaviorTree.CPP
// versions retry within the same tick; the outcome over ticks is the same.)
#pragma once

#include <memory>
#include <string>

#include "rtamp/bt/decorator.hpp"

namespace rtamp::bt {

class Retry : public Decorator {
 public:
  Retry(std::string name, int num_attempts, std::unique_ptr<Node> child = nullptr);
  Retry(int num_attempts, std::unique_ptr<Node> child) : Retry("Retry", num_attempts, std::move(child)) {}
  std::string_view type_id() const override { return "RetryUntilSuccessful"; }
  bool btcpp_builtin() const override { return true; }
  int num_attempts() const { return num_attempts_; }
  // Failed attempts in the current run.
  int failures() const { return failures_; }
  void collect_ports(std::vector<Port>& out) const override;

 protected:
  Status on_tick() override;
  void on_reset() override { failures_ = 0; }

 private:
  int num_attempts_;
  int failures_ = 0;
};

}  // namespace rtamp::bt
