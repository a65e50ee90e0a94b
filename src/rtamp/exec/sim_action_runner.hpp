// The arm behind the tree's Move nodes in simulation: an exec::ActionRunner
// that runs move(o, l) as the sim layer's pick(o) then place(o, l) skills
// (the paper's skill library, Fig. 2), one move at a time.
//
// Failure and preemption never leave the arm in a bad spot:
//  - a move that fails while holding its object first puts it back where it
//    came from ("recovering"), then reports FAILURE;
//  - a halted move (a reactive state-condition subtree preempts its move, or
//    the tree is halted) puts a held object back, or backs the empty gripper
//    straight up ("returning"); until that is done returning() is true, and a
//    move started meanwhile waits and begins when the arm is free.
// Invariants: at most one move runs; current() names it ("" if none); the
// hand is where the last place ended (hand(), "" = home at first).
#pragma once

#include <functional>
#include <string>

#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/sim/skill_runner.hpp"

namespace rtamp::exec {

class SimActionRunner final : public ActionRunner {
 public:
  SimActionRunner(sim::Simulation& sim, sim::SkillRunner& skills, sim::Controller& controller)
      : sim_(sim), skills_(skills), controller_(controller) {}

  bt::Status start(const plan::ActionTuple& t) override;
  bt::Status running(const plan::ActionTuple& t) override;
  void halt(const plan::ActionTuple& t) override;

  // True while the arm finishes after a halted move (puts its object back, or
  // backs off); the tree should wait.
  bool returning();
  // Where the thing held while returning goes back to.
  const std::string& source() const { return back_from_; }

  // The running (or waiting) move: its action, thing and destination ("" if none).
  const std::string& current() const { return current_; }
  const std::string& thing() const { return thing_; }
  const std::string& destination() const { return to_; }
  // Where the hand is when no move runs: the location of the last place ("" at first: home).
  const std::string& hand() const { return hand_; }

  int succeeded = 0, failed = 0;
  std::string last_failure;  // "move(o1, r2): why" of the last failed move
  // Called with ("start" | "finished" | "failed" | "recovering" | "halted" |
  // "returning" | "returned", action or thing, reason).
  std::function<void(const char*, const std::string&, const std::string&)> on_event;

 private:
  enum class Phase { Picking, Placing, Recovering };

  bt::Status begin();
  bt::Status fail_or_recover(const std::string& why);
  bt::Status finish(bt::Status s, const std::string& why);
  bool holds(const std::string& thing) const { return sim_.held() >= 0 && sim_.held() == sim_.find(thing); }
  void event(const char* what, const std::string& subject, const std::string& why) const {
    if (on_event) on_event(what, subject, why);
  }

  sim::Simulation& sim_;
  sim::SkillRunner& skills_;
  sim::Controller& controller_;
  std::string current_, thing_, to_, from_, failure_, hand_;
  Phase phase_ = Phase::Picking;
  bool returning_ = false, waiting_ = false;
  std::string back_thing_, back_from_;  // the halted move's object and source, while returning
};

}  // namespace rtamp::exec
