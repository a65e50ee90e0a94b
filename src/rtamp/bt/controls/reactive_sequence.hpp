// rtamp::bt::ReactiveSequence — sequence without memory (BehaviorTree.CPP
// `ReactiveSequence`, py_trees `Sequence(memory=False)`).
//
// Every tick starts again from the first child: FAILURE of a child is FAILURE,
// RUNNING is RUNNING, all SUCCESS is SUCCESS. When an earlier child now fails or
// runs, a later child that was RUNNING is halted (children after the deciding
// one are reset). Empty: SUCCESS.
#pragma once

#include <string>

#include "rtamp/bt/composite.hpp"

namespace rtamp::bt {

class ReactiveSequence : public Composite {
 public:
  explicit ReactiveSequence(std::string name = "ReactiveSequence") : Composite(std::move(name)) {}
  std::string_view type_id() const override { return "ReactiveSequence"; }
  bool btcpp_builtin() const override { return true; }

 protected:
  Status on_tick() override;
};

}  // namespace rtamp::bt
