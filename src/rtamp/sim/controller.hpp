// The controller: executes one skill's motion plan in the simulation — the paper's
// low-level "motor control" under a behavior-tree action node (Section IV-C). It tracks
// a robot::Trajectory (joint position + velocity targets each physics step), performs
// the gripper events (close -> weld the object when both fingers touch it; open ->
// release), and reports the skill's status the way a BT action does:
// RUNNING until done, then SUCCESS or FAILURE with a reason.
//
// Failure conditions (each with a reason string):
//  - the plan is empty / the target was unreachable (the caller passes the reason);
//  - the fingers closed without touching the object (grasp missed), or stopped
//    without both touching it (on a neighbour, say): the simulation records which,
//    and where (Simulation::last_failed_grasp, the robot's evidence), and the fingers
//    open again before the failure is reported, so nothing rides along;
//  - the object left the hand while it had to be held (taken away by the operator,
//    hidden, or slipped more than slip_tolerance from its grasp pose);
//  - the object to grasp vanished before the grasp;
//  - tracking diverged (joint error above tracking_limit, e.g. the arm is blocked);
//  - the plan's release check refused to let go (a place the rule book refuses at the
//    moment of the release: a person filled the location since the place began); the
//    object is kept, the rest of the plan (its retreat) runs, then FAILURE with that reason.
// The trajectory clock pauses while the gripper is closing or opening, so plans need no
// exact gripper timing. halt() stops where the arm is (a BT preemption). A pick opens
// the fingers as it starts (a grasp halted while closing leaves them closed).
// Invariants: at most one plan runs; after SUCCESS of a plan ending with the object in
// hand, sim.held() is that object; after a release, it is -1; a refused release leaves
// the object in hand (sim.held() is still it) and ends the plan FAILURE.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rtamp/robot/trajectory.hpp"
#include "rtamp/sim/simulation.hpp"

namespace rtamp::sim {

enum class Status { Idle, Running, Success, Failure };
const char* to_string(Status s);

struct GripperEvent {
  double time = 0;     // trajectory time at which it happens
  bool close = false;  // close (grasp `object`) or open (release)
};

// What the controller executes: a trajectory, gripper events, and the thing involved.
struct MotionPlan {
  robot::Trajectory trajectory;
  std::vector<GripperEvent> events;  // sorted by time
  std::string object;                // grasped by a close event, released by an open one
  bool absent_ok = false;            // a pick toward where `object` is perceived: it may not be there
  double cost = 0;                   // motion cost (tool path length, m), for reports
  std::string skill;                 // "pick", "place", ... (for reports)
  // Asked when an open event is due with `object` in hand: "" lets go; else why it may
  // not be let go of here now (then it is kept and the plan ends FAILURE with that).
  std::function<std::string()> release_check;
};

struct ControllerOptions {
  double closed_opening = 0.0;     // finger target when closing (they stop on the object)
  double gripper_timeout = 1.0;    // s to close on / open from an object
  double settle_time = 0.3;        // s after the trajectory before reporting
  double slip_tolerance = 0.02;    // m
  double tracking_limit = 0.25;    // rad
};

class Controller {
 public:
  explicit Controller(Simulation& sim, ControllerOptions options = {});

  // Starts a plan (replacing any running one).
  void start(MotionPlan plan);
  // Fails at once with `why` (e.g. "o1 unreachable": IK found no solution).
  void fail(std::string why);
  // One control update for the current physics step; call before sim.step().
  Status update();
  // step(): update() + sim.step(); run(): until not Running or `max_time` of sim time.
  Status step();
  Status run(double max_time = 120);
  void halt();

  Status status() const { return status_; }
  const std::string& reason() const { return reason_; }
  const MotionPlan& plan() const { return plan_; }
  double elapsed() const;  // sim time since start

 private:
  enum class Gripper { Idle, Closing, Opening };
  void finish(Status s, std::string why = {});
  void fail_open(std::string why);  // opens the fingers, then fails with `why`
  bool must_hold() const;

  Simulation& sim_;
  ControllerOptions options_;
  MotionPlan plan_;
  Status status_ = Status::Idle;
  std::string reason_;
  int object_ = -1;
  double t0_ = 0;        // sim time at start
  double clock_ = 0;     // trajectory time (paused during gripper actions)
  double gripper_t0_ = 0;
  double done_at_ = -1;  // sim time the trajectory ended
  std::size_t next_event_ = 0;
  Gripper gripper_ = Gripper::Idle;
  bool holding_ = false;  // the plan has grasped the object and not released it yet
  std::string failing_;   // a failed grasp's reason, reported once the fingers are open
  std::string refused_;   // the release check's refusal, reported once the plan has run
  Eigen::Isometry3d grasp_rel_ = Eigen::Isometry3d::Identity();
};

}  // namespace rtamp::sim
