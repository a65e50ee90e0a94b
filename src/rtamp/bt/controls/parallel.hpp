// rtamp::bt::Parallel — ticks its children "at once" (each tick, every child not
// yet finished in this run), with BehaviorTree.CPP 4 `Parallel` thresholds:
// success_count / failure_count, a negative value counting from the number of
// children (-1 = all of them).
//
// A run starts with every child reset. Each tick, pending children (not yet
// SUCCESS or FAILURE in this run) are ticked, all of them; then, with n children,
// s successes and f failures and S, F the resolved thresholds:
//   FAILURE  if (F > 0 and f >= F) or n - f < S  (success has become impossible)
//   SUCCESS  else if s >= S
//   RUNNING  otherwise.
// Failure is checked first (py_trees precedence). On SUCCESS/FAILURE, children
// still RUNNING are halted. py_trees policies map to: SuccessOnAll = (S=-1, F=1),
// SuccessOnOne = (S=1, F=1). Difference from BehaviorTree.CPP: it stops ticking
// children as soon as a threshold is met within the loop; we tick every pending
// child first. Empty: SUCCESS, whatever the thresholds.
#pragma once

#include <string>

#include "rtamp/bt/composite.hpp"

namespace rtamp::bt {

class Parallel : public Composite {
 public:
  explicit Parallel(std::string name = "Parallel", int success_count = -1, int failure_count = 1)
      : Composite(std::move(name)), success_count_(success_count), failure_count_(failure_count) {}
  static std::unique_ptr<Parallel> success_on_all(std::string name = "Parallel") {
    return std::make_unique<Parallel>(std::move(name), -1, 1);
  }
  static std::unique_ptr<Parallel> success_on_one(std::string name = "Parallel") {
    return std::make_unique<Parallel>(std::move(name), 1, 1);
  }

  std::string_view type_id() const override { return "Parallel"; }
  bool btcpp_builtin() const override { return true; }
  int success_count() const { return success_count_; }
  int failure_count() const { return failure_count_; }
  void set_thresholds(int success_count, int failure_count) {
    success_count_ = success_count;
    failure_count_ = failure_count;
  }
  // A threshold resolved against the current number of children.
  std::size_t resolve(int threshold) const;
  void collect_ports(std::vector<Port>& out) const override;

 protected:
  Status on_tick() override;

 private:
  int success_count_;
  int failure_count_;
};

}  // namespace rtamp::bt
