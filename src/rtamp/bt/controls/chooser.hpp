// rtamp::bt::Chooser — a selector with commitment (py_trees 2.0 `Chooser`; the
// root of each action-condition subtree in the paper, Fig. 3b: "prevents
// interruption from higher priority of sibling subtrees", so an action in
// progress completes).
//
// Not running (new run): ticks children in order like a selector and commits to
// the first that returns RUNNING or SUCCESS, returning its status; all FAILURE is
// FAILURE. Running (committed): ticks only the committed child — higher-priority
// siblings are not even evaluated — and returns its status as is: FAILURE of the
// committed child is FAILURE, without falling through to later children in the
// same tick. The next tick after the child finishes picks afresh from the top.
// Empty: FAILURE. Inserting/removing before the committed child keeps the
// commitment; removing/replacing the committed child drops it (the next tick
// picks afresh). Exported to BehaviorTree.CPP XML as the custom control "Chooser".
#pragma once

#include <cstddef>
#include <limits>
#include <string>

#include "rtamp/bt/composite.hpp"

namespace rtamp::bt {

class Chooser : public Composite {
 public:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  explicit Chooser(std::string name = "Chooser") : Composite(std::move(name)) {}
  std::string_view type_id() const override { return "Chooser"; }
  // Index of the committed child, kNone if none.
  std::size_t committed_index() const { return current_; }

 protected:
  Status on_tick() override;
  void on_reset() override { current_ = kNone; }
  void child_inserted(std::size_t pos) override;
  void child_removed(std::size_t pos) override;
  void child_replaced(std::size_t pos) override;

 private:
  std::size_t current_ = kNone;
};

}  // namespace rtamp::bt
