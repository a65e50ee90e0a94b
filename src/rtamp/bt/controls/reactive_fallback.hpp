// rtamp::bt::ReactiveFallback (alias ReactiveSelector) — fallback without memory
// (BehaviorTree.CPP `ReactiveFallback`, py_trees `Selector(memory=False)`).
//
// Every tick starts again from the first child: SUCCESS of a child is SUCCESS,
// RUNNING is RUNNING, FAILURE moves on; all FAILURE is FAILURE. A higher-priority
// child that becomes ready preempts a lower one: the lower child, if RUNNING, is
// halted (children after the deciding one are reset). Empty: FAILURE.
#pragma once

#include <string>

#include "rtamp/bt/composite.hpp"

namespace rtamp::bt {

class ReactiveFallback : public Composite {
 public:
  explicit ReactiveFallback(std::string name = "ReactiveFallback") : Composite(std::move(name)) {}
  std::string_view type_id() const override { return "ReactiveFallback"; }
  bool btcpp_builtin() const override { return true; }

 protected:
  Status on_tick() override;
};

using ReactiveSelector = ReactiveFallback;

}  // namespace rtamp::bt
