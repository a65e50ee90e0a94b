// The arm behind the tree's Move nodes: an ActionRunner (subtree_builder.hpp)
// that runs move(o, l) on an exec::World, one move at a time.
//
// A move the tree starts while the world is still busy (making the arm safe
// after a halt) waits and begins once the world is free. Every start, end and
// halt is reported through on_event ("start" | "finished" | "failed" |
// "halted", action, reason). A move halted after it has put its thing where
// it was going (placed(), e.g. a state-form tree whose post-condition holds
// while the arm retreats) is done: it counts and is reported as "finished",
// whatever tree form halted it.
// Invariants: at most one move is current(); current() is "" when none runs
// or waits; succeeded + failed counts every move that began and ended.
#pragma once

#include <functional>
#include <string>

#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/exec/world.hpp"

namespace rtamp::exec {

class WorldRunner final : public ActionRunner {
 public:
  explicit WorldRunner(World& world) : world_(world) {}

  bt::Status start(const plan::ActionTuple& t) override;
  bt::Status running(const plan::ActionTuple& t) override;
  void halt(const plan::ActionTuple& t) override;

  // The running (or waiting) move ("" action if none).
  const Move& current() const { return current_; }
  bool waiting() const { return waiting_; }

  int succeeded = 0, failed = 0;
  std::string last_failure;  // "move(o1, r2): why"
  Move last_failed;          // the move that failed last
  std::function<void(const char*, const std::string&, const std::string&)> on_event;
  // Whether the running move's thing is already at its destination (as last perceived).
  std::function<bool(const Move&)> placed;

 private:
  bt::Status begin();
  bt::Status finish(bt::Status s, const std::string& why);
  void event(const char* what, const std::string& action, const std::string& why) const {
    if (on_event) on_event(what, action, why);
  }

  World& world_;
  Move current_;
  bool waiting_ = false;
};

}  // namespace rtamp::exec
