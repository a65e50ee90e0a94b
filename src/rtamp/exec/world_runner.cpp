#include "rtamp/exec/world_runner.hpp"

namespace rtamp::exec {

bt::Status WorldRunner::start(const plan::ActionTuple& t) {
  current_ = Move{t.action, t.thing, t.from, t.to};
  if (world_.busy()) {
    waiting_ = true;
    return bt::Status::Running;
  }
  return begin();
}

bt::Status WorldRunner::running(const plan::ActionTuple&) {
  if (waiting_) return world_.busy() ? bt::Status::Running : begin();
  std::string why;
  switch (world_.poll(&why)) {
    case MoveStatus::Succeeded: return finish(bt::Status::Success, {});
    case MoveStatus::Failed: return finish(bt::Status::Failure, why);
    case MoveStatus::Idle: return finish(bt::Status::Failure, "the world is not running the move");
    case MoveStatus::Running: break;
  }
  return bt::Status::Running;
}

void WorldRunner::halt(const plan::ActionTuple&) {
  if (current_.action.empty()) return;
  if (!waiting_ && placed && placed(current_)) {
    world_.halt();  // only the retreat is cut short
    ++succeeded;
    event("finished", current_.action, "placed; halted while the arm retreated");
  } else if (!waiting_) {
    world_.halt();
    event("halted", current_.action, "");
  }
  waiting_ = false;
  current_ = Move{};
}

bt::Status WorldRunner::begin() {
  waiting_ = false;
  event("start", current_.action, "");
  world_.start(current_);
  std::string why;
  const MoveStatus s = world_.poll(&why);
  if (s == MoveStatus::Failed) return finish(bt::Status::Failure, why);
  if (s == MoveStatus::Succeeded) return finish(bt::Status::Success, {});
  return bt::Status::Running;
}

bt::Status WorldRunner::finish(bt::Status s, const std::string& why) {
  if (s == bt::Status::Failure) {
    ++failed;
    last_failure = current_.action + ": " + why;
    last_failed = current_;
  } else {
    ++succeeded;
  }
  event(s == bt::Status::Success ? "finished" : "failed", current_.action, why);
  current_ = Move{};
  return s;
}

}  // namespace rtamp::exec
