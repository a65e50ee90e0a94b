// rtamp::bt::Sequence — sequence with memory of the running child
// (BehaviorTree.CPP `Sequence`, py_trees `Sequence(memory=True)`; paper Fig. 3 "→").
//
// Ticks children in order from where it left off: a child that returns RUNNING
// makes the Sequence return RUNNING, and the next tick resumes at that child
// without re-ticking the children before it; FAILURE of a child ends the run with
// FAILURE (the next tick starts again from the first child); SUCCESS of all
// children is SUCCESS. Empty: SUCCESS. Children after the deciding one are reset
// (halted if RUNNING). Inserting/removing a child before the running child keeps
// the running child current; removing the running child resumes at the child
// that takes its place.
//
// Yield (an rtamp extension, off by default): with set_yield(f), when a child
// succeeds, more children remain and f() is true, the Sequence returns RUNNING
// at once and the next tick resumes at the next child. A caller uses it to get a
// moment between two children in which nothing runs (e.g. to reconfigure the
// tree before the next step starts).
#pragma once

#include <functional>
#include <string>

#include "rtamp/bt/composite.hpp"

namespace rtamp::bt {

class Sequence : public Composite {
 public:
  explicit Sequence(std::string name = "Sequence") : Composite(std::move(name)) {}
  std::string_view type_id() const override { return "Sequence"; }
  bool btcpp_builtin() const override { return true; }
  // Index of the child the next tick resumes at (meaningful while RUNNING).
  std::size_t current_index() const { return index_; }
  void set_yield(std::function<bool()> yield) { yield_ = std::move(yield); }

 protected:
  Status on_tick() override;
  void on_reset() override { index_ = 0; }
  void child_inserted(std::size_t pos) override;
  void child_removed(std::size_t pos) override;

 private:
  std::size_t index_ = 0;
  std::function<bool()> yield_;
};

}  // namespace rtamp::bt
