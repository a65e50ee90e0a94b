// rtamp::bt::Fallback (alias Selector) — fallback with memory of the running
// child (BehaviorTree.CPP `Fallback`, py_trees `Selector(memory=True)`; paper "?").
//
// Ticks children in order from where it left off: RUNNING makes the Fallback
// RUNNING and the next tick resumes at that child (earlier children are not
// re-ticked); SUCCESS of a child ends the run with SUCCESS; FAILURE moves on to the
// next child; all children failing is FAILURE. Empty: FAILURE. Children after the
// deciding one are reset. Changes before the running child keep it current (as
// Sequence).
#pragma once

#include <string>

#include "rtamp/bt/composite.hpp"

namespace rtamp::bt {

class Fallback : public Composite {
 public:
  explicit Fallback(std::string name = "Fallback") : Composite(std::move(name)) {}
  std::string_view type_id() const override { return "Fallback"; }
  bool btcpp_builtin() const override { return true; }
  std::size_t current_index() const { return index_; }

 protected:
  Status on_tick() override;
  void on_reset() override { index_ = 0; }
  void child_inserted(std::size_t pos) override;
  void child_removed(std::size_t pos) override;

 private:
  std::size_t index_ = 0;
};

using Selector = Fallback;

}  // namespace rtamp::bt
