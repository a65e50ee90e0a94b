#include "rtamp/exec/sim_action_runner.hpp"

namespace rtamp::exec {

bt::Status SimActionRunner::start(const plan::ActionTuple& t) {
  current_ = t.action;
  to_ = t.to;
  from_ = t.from;
  thing_ = t.thing;
  if (returning()) {  // the arm still finishes after a halted move: start when it is done
    waiting_ = true;
    return bt::Status::Running;
  }
  return begin();
}

bt::Status SimActionRunner::running(const plan::ActionTuple&) {
  if (waiting_) return returning() ? bt::Status::Running : begin();
  const sim::Status s = controller_.status();
  if (s == sim::Status::Running) return bt::Status::Running;
  if (s == sim::Status::Failure) return fail_or_recover(controller_.reason());
  switch (phase_) {
    case Phase::Picking:
      phase_ = Phase::Placing;
      if (!skills_.start_place(to_)) return fail_or_recover(controller_.reason());
      return bt::Status::Running;
    case Phase::Placing:
      hand_ = to_;
      return finish(bt::Status::Success, {});
    case Phase::Recovering:
      hand_ = from_;
      return finish(bt::Status::Failure, failure_);
  }
  return bt::Status::Running;
}

void SimActionRunner::halt(const plan::ActionTuple&) {
  if (waiting_) {  // never started: nothing to stop
    waiting_ = false;
    current_.clear();
    return;
  }
  controller_.halt();
  event("halted", current_, "");
  back_thing_ = thing_;
  back_from_ = from_;
  if (holds(thing_)) {
    if (skills_.start_place(from_)) {
      returning_ = true;
      hand_ = from_;
      event("returning", current_, "putting " + thing_ + " back in " + from_);
    } else {
      sim_.detach();
    }
  } else if (skills_.start_retreat() && controller_.status() == sim::Status::Running) {
    returning_ = true;
    event("returning", current_, "backing off");
  }
  current_.clear();
}

bool SimActionRunner::returning() {
  if (returning_ && controller_.status() != sim::Status::Running) {
    returning_ = false;
    if (controller_.status() == sim::Status::Failure && holds(back_thing_)) sim_.detach();
    event("returned", back_thing_, controller_.reason());
  }
  return returning_;
}

bt::Status SimActionRunner::begin() {
  waiting_ = false;
  phase_ = Phase::Picking;
  event("start", current_, "");
  if (!skills_.start_pick(thing_)) return finish(bt::Status::Failure, controller_.reason());
  return bt::Status::Running;
}

// A failed move must not leave the object in the gripper: put it back where
// it came from first (the failure is reported when that is done).
bt::Status SimActionRunner::fail_or_recover(const std::string& why) {
  failure_ = why;
  if (phase_ != Phase::Recovering && holds(thing_)) {
    phase_ = Phase::Recovering;
    event("recovering", current_, why + "; putting " + thing_ + " back in " + from_);
    if (skills_.start_place(from_)) return bt::Status::Running;
    sim_.detach();
  }
  return finish(bt::Status::Failure, why);
}

bt::Status SimActionRunner::finish(bt::Status s, const std::string& why) {
  if (s == bt::Status::Failure) {
    ++failed;
    last_failure = current_ + ": " + why;
  } else {
    ++succeeded;
  }
  event(s == bt::Status::Success ? "finished" : "failed", current_, why);
  current_.clear();
  return s;
}

}  // namespace rtamp::exec
