#include "rtamp/sim/controller.hpp"

#include <cmath>

namespace rtamp::sim {

const char* to_string(Status s) {
  switch (s) {
    case Status::Idle: return "IDLE";
    case Status::Running: return "RUNNING";
    case Status::Success: return "SUCCESS";
    case Status::Failure: return "FAILURE";
  }
  return "?";
}

Controller::Controller(Simulation& sim, ControllerOptions options) : sim_(sim), options_(options) {}

double Controller::elapsed() const { return sim_.time() - t0_; }

void Controller::start(MotionPlan plan) {
  plan_ = std::move(plan);
  status_ = Status::Running;
  reason_.clear();
  t0_ = sim_.time();
  clock_ = 0;
  done_at_ = -1;
  next_event_ = 0;
  gripper_ = Gripper::Idle;
  failing_.clear();
  refused_.clear();
  object_ = plan_.object.empty() ? -1 : sim_.find(plan_.object);
  holding_ = false;
  if (plan_.trajectory.empty()) return finish(Status::Failure, "empty motion plan");
  if (object_ >= 0 && !sim_.thing(object_).present) object_ = -1;
  if (!plan_.object.empty() && object_ < 0 && !plan_.absent_ok)
    return finish(Status::Failure, "'" + plan_.object + "' is not in the scene");
  // A plan whose first gripper event is "open" starts with the object in hand.
  if (!plan_.events.empty() && !plan_.events.front().close) {
    if (object_ < 0 || sim_.held() != object_)
      return finish(Status::Failure, "not holding '" + plan_.object + "'");
    holding_ = true;
    grasp_rel_ = sim_.tool_pose().inverse() * sim_.pose(object_);
  }
  // Begin from where the arm is: the plan's start must be close to it.
  const robot::Joints q = sim_.arm_q();
  if (robot::max_joint_delta(q, plan_.trajectory.start()) > options_.tracking_limit)
    return finish(Status::Failure, "the plan starts away from the arm's configuration");
  // A pick approaches with open fingers (a grasp halted while closing leaves them closed).
  if (!plan_.events.empty() && plan_.events.front().close && sim_.held() < 0)
    sim_.set_finger_target(sim_.finger_max());
}

void Controller::fail(std::string why) {
  plan_ = MotionPlan{};
  t0_ = sim_.time();
  finish(Status::Failure, std::move(why));
}

void Controller::fail_open(std::string why) {
  failing_ = std::move(why);
  gripper_t0_ = sim_.time();
  sim_.set_finger_target(sim_.finger_max());
  gripper_ = Gripper::Opening;
}

void Controller::finish(Status s, std::string why) {
  status_ = s;
  reason_ = std::move(why);
  // Hold where the arm is.
  if (s == Status::Failure) sim_.set_arm_target(sim_.arm_q());
}

void Controller::halt() {
  if (status_ != Status::Running) return;
  sim_.set_arm_target(sim_.arm_q());
  status_ = Status::Idle;
  reason_ = "halted";
}

bool Controller::must_hold() const { return holding_; }

Status Controller::update() {
  if (status_ != Status::Running) return status_;
  const double now = sim_.time();
  const double dt = sim_.timestep();

  // The object must stay in hand while held.
  if (holding_) {
    if (sim_.held() != object_ || !sim_.thing(object_).present)
      return finish(Status::Failure, "'" + plan_.object + "' was taken from the gripper"), status_;
    const Eigen::Isometry3d rel = sim_.tool_pose().inverse() * sim_.pose(object_);
    if ((rel.translation() - grasp_rel_.translation()).norm() > options_.slip_tolerance)
      return finish(Status::Failure, "'" + plan_.object + "' slipped in the gripper"), status_;
  }

  // Gripper actions in progress pause the trajectory clock.
  if (gripper_ == Gripper::Closing) {
    if (object_ >= 0 && !sim_.thing(object_).present)
      return finish(Status::Failure, "'" + plan_.object + "' vanished before the grasp"), status_;
    if (object_ >= 0 && sim_.fingers_touch(object_)) {
      sim_.attach(object_);
      holding_ = true;
      grasp_rel_ = sim_.tool_pose().inverse() * sim_.pose(object_);
      // Squeeze lightly: a target a little inside the object.
      sim_.set_finger_target(std::max(0.0, sim_.finger_opening() - 0.003));
      gripper_ = Gripper::Idle;
    } else if (sim_.finger_opening() < 0.002) {
      sim_.note_failed_grasp(true);
      fail_open("grasp of '" + plan_.object + "' missed (the fingers closed on nothing)");
    } else if (now - gripper_t0_ > options_.gripper_timeout) {
      sim_.note_failed_grasp(false);
      fail_open("grasp of '" + plan_.object + "' failed (the fingers stopped without holding it)");
    }
  } else if (gripper_ == Gripper::Opening) {
    if (sim_.finger_opening() > 0.9 * sim_.finger_max() || now - gripper_t0_ > options_.gripper_timeout) {
      gripper_ = Gripper::Idle;
      if (!failing_.empty()) return finish(Status::Failure, std::move(failing_)), status_;
    }
  }

  if (gripper_ == Gripper::Idle) {
    // Events due at the current trajectory time.
    while (gripper_ == Gripper::Idle && next_event_ < plan_.events.size() &&
           plan_.events[next_event_].time <= clock_ + 1e-12) {
      const GripperEvent& e = plan_.events[next_event_++];
      gripper_t0_ = now;
      if (e.close) {
        if (object_ < 0 && !plan_.absent_ok) return finish(Status::Failure, "nothing to grasp"), status_;
        sim_.set_finger_target(options_.closed_opening);
        gripper_ = Gripper::Closing;
      } else {
        if (holding_ && plan_.release_check)
          if (std::string why = plan_.release_check(); !why.empty()) {
            refused_ = std::move(why);  // kept in hand: the plan's retreat takes it back up
            continue;
          }
        if (object_ >= 0 && sim_.held() == object_) sim_.detach();
        holding_ = false;
        sim_.set_finger_target(sim_.finger_max());
        gripper_ = Gripper::Opening;
      }
    }
  }

  const robot::Trajectory::Sample s = plan_.trajectory.sample(clock_);
  if (gripper_ == Gripper::Idle) {
    sim_.set_arm_target(s.q, s.qd);
    if (clock_ < plan_.trajectory.duration()) clock_ = std::min(plan_.trajectory.duration(), clock_ + dt);
  } else {
    sim_.set_arm_target(s.q);
  }

  if (robot::max_joint_delta(sim_.arm_q(), s.q) > options_.tracking_limit)
    return finish(Status::Failure, "the arm cannot follow its trajectory (blocked?)"), status_;

  const bool trajectory_done = clock_ >= plan_.trajectory.duration() && gripper_ == Gripper::Idle &&
                               next_event_ >= plan_.events.size();
  if (trajectory_done) {
    if (done_at_ < 0) done_at_ = now;
    if (now - done_at_ >= options_.settle_time) {
      if (!refused_.empty()) return finish(Status::Failure, std::move(refused_)), status_;
      finish(Status::Success);
    }
  }
  return status_;
}

Status Controller::step() {
  Status s = update();
  sim_.step();
  return s;
}

Status Controller::run(double max_time) {
  const double until = sim_.time() + max_time;
  while (status_ == Status::Running && sim_.time() < until) step();
  if (status_ == Status::Running) {
    halt();
    finish(Status::Failure, "timed out");
  }
  return status_;
}

}  // namespace rtamp::sim
