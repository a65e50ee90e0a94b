// The running MuJoCo world of a scenario (docs/design.md "Simulation"): loads the MJCF of
// mjcf_builder.hpp from memory, steps the physics with exact gravity compensation of
// the arm, grasps with weld equalities, and lets the operator teleport, hide and show
// bodies. The paper's execution layer runs on top of this (Section IV-C, Fig. 2's
// "motor control" box); perception, controller and operator use it.
//
// Invariants:
//  - a "thing" is a movable body: a scenario object or container, or a reserved spare
//    body; a thing is present (in the scene, contacts on) or hidden (parked far below
//    the table, contacts off, re-parked every step);
//  - at most one weld (gripper, thing) is active; held() names it (-1: none);
//  - activating a weld first rewrites its eq_data with the current relative pose, so a
//    grasp never moves the object (MuJoCo 2.2.2 keeps the switch in mjModel::eq_active,
//    so one Simulation owns its model and no other mjData may share it);
//  - step() applies: ctrl = joint targets, qfrc_applied = qfrc_bias + damping * qd* +
//    M qdd* on the arm dofs (mj_step1 / mj_step2), which holds any pose against gravity.
//    The motor torque of a joint — servo kp (q* − q), feed-forward qfrc_bias + M qdd*,
//    and velocity feedback damping (qd* − qd), which MuJoCo applies as implicit joint
//    damping — is kept within the actuator's forcerange (the UR5's published effort
//    limits, models/ur5.xml) by clamping the feed-forward; steps where that clamp acts
//    are counted (torque_limited_steps()).
#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/robot/joints.hpp"
#include "rtamp/sim/mjcf_builder.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

struct SimOptions {
  MjcfOptions mjcf;
  double collision_tolerance = 5e-4;  // penetration (m) tolerated by config_collides
  // The upper arm and forearm must stay this far above the table in config_collides (the
  // skills only check their transits; this keeps the approach below it clear too):
  // the lowest point of their capsules, computed directly (no contact margins needed).
  double arm_table_clearance = 0.01;
  // config_collides also refuses configurations whose elbow is lower than this above the
  // table top (z = 0): an elbow-down UR5 lays its upper arm on the table while it
  // approaches, which the skills' transit check cannot see.
  double min_elbow_height = 0.15;
};

// A movable body of the model.
struct Thing {
  std::string name;   // scenario name; for an unused spare, empty
  std::string cls;    // "block", "tray", ...
  bool container = false;
  bool spare = false;    // one of the reserved bodies
  bool present = true;   // in the scene (false: hidden / parked)
  world::Vec3 size{};    // footprint and height (m)
  std::string body_name;
  int body = -1, qpos = -1, dof = -1, eq = -1;
  int park_index = -1;   // parking slot while hidden
  int geom_begin = 0, geom_count = 0;
};

// MuJoCo's warning counters (d->warning[i].number) by name.
struct Warnings {
  std::array<int, mjNWARNING> count{};
  int total() const;
  static const char* name(int i);
};

class Simulation {
 public:
  explicit Simulation(const world::Scenario& scenario, SimOptions options = {});
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const mjModel* model() const { return m_; }
  const mjData* data() const { return d_; }
  const world::Scenario& scenario() const { return scenario_; }
  const SimOptions& options() const { return options_; }
  const std::string& mjcf() const { return mjcf_; }
  double time() const { return d_->time; }
  double timestep() const { return m_->opt.timestep; }

  // One physics step with the current targets (see invariants).
  void step();
  void step(int n) {
    for (int i = 0; i < n; ++i) step();
  }

  // Arm joint targets: position, and optionally velocity and acceleration feed-forward.
  void set_arm_target(const robot::Joints& q, const robot::Joints& qd = {}, const robot::Joints& qdd = {});
  const robot::Joints& arm_target() const { return q_target_; }
  // Both fingers' target: distance of each inner face from the tool axis (m).
  void set_finger_target(double half_opening);
  double finger_target() const { return finger_target_; }
  double finger_max() const { return options_.mjcf.finger_max; }

  robot::Joints arm_q() const;
  robot::Joints arm_qd() const;
  double finger_opening() const;  // mean of the two finger joints (m)
  double finger_speed() const;    // mean |velocity| of the two finger joints (m/s)
  Eigen::Isometry3d site_pose(int site) const;
  Eigen::Isometry3d tool_pose() const { return site_pose(tcp_site_); }
  Eigen::Isometry3d flange_pose() const { return site_pose(flange_site_); }
  // Puts the arm at q at rest (targets too), recomputing kinematics. For setup and tests.
  void set_arm_configuration(const robot::Joints& q);

  // Movable bodies.
  const std::vector<Thing>& things() const { return things_; }
  const Thing& thing(int i) const { return things_[static_cast<std::size_t>(i)]; }
  int find(const std::string& name) const;  // present or hidden named thing; -1 if none
  Eigen::Isometry3d pose(int thing) const;
  Eigen::Vector3d position(int thing) const;  // body origin
  Eigen::Vector3d velocity(int thing) const;
  // Teleport (zero velocity). The body must not be hidden.
  void set_pose(int thing, const Eigen::Isometry3d& pose);
  // Park a thing out of view with its contacts off (it keeps its name: find() still
  // returns it, present == false). Releases it if held.
  void hide(int thing);
  // Bring a hidden named thing back at `pose`.
  void show(int thing, const Eigen::Isometry3d& pose);
  // Give an unused spare body of the right kind a name and put it at `pose`. A block's
  // geom takes `size` (mass and inertia stay those of the spare); a tray keeps the
  // spare's size. Returns the thing index. Throws rtamp::Error when no spare is left.
  int add(const std::string& name, const std::string& cls, bool container, const Eigen::Isometry3d& pose,
          const world::Vec3& size);

  // Grasping.
  bool fingers_touch(int thing) const;  // both fingers in contact with it
  void attach(int thing);               // weld at the current relative pose
  void detach();  // also frees the reserved spot
  int held() const { return held_; }
  // The last grasp that failed (time < 0: none yet): when, where the tool point was, and
  // whether the fingers closed on nothing (else they stopped on something they could not
  // hold). The controller notes it (as it attaches a thing it grasped): it is what the
  // robot knows of its gripper, and camera perception takes it as evidence.
  struct FailedGrasp {
    double time = -1;
    Eigen::Vector3d tool = Eigen::Vector3d::Zero();
    bool empty = false;
  };
  void note_failed_grasp(bool empty) { failed_grasp_ = {time(), tool_pose().translation(), empty}; }
  const FailedGrasp& last_failed_grasp() const { return failed_grasp_; }
  // The spot the arm is about to put the held thing on (footprint, gap included):
  // free_spot() treats it as taken, so the operator does not put things there.
  void reserve_spot(const world::Footprint& f) { reserved_ = f; }
  void clear_reserved_spot() { reserved_.reset(); }
  const std::optional<world::Footprint>& reserved_spot() const { return reserved_; }

  // Collision check of an arm configuration on a scratch mjData holding the current
  // state (objects where they are now, the held thing carried along): true if an arm,
  // gripper or held-thing geom penetrates anything else by more than the tolerance.
  // Things in `ignore` are excluded (e.g. the contents of a carried tray).
  bool config_collides(const robot::Joints& q, const std::vector<int>& ignore = {}) const;

  Warnings warnings() const;
  // Physics steps in which some arm joint's motor torque hit its effort limit.
  long torque_limited_steps() const { return torque_limited_steps_; }

  // Re-run kinematics after direct state edits (set_pose etc. do it themselves).
  void forward();

 private:
  void park(const Thing& t);
  void set_contacts(const Thing& t, bool on);

  world::Scenario scenario_;
  SimOptions options_;
  std::string mjcf_;
  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
  mjData* scratch_ = nullptr;
  std::vector<Thing> things_;
  std::vector<int> thing_of_body_;  // body id -> thing index or -1
  std::vector<char> arm_body_;      // body id -> part of arm or gripper
  std::vector<int> hidden_;         // indices of hidden things (re-parked each step)
  std::vector<std::array<int, 2>> geom_contact_;  // original contype/conaffinity
  robot::Joints q_target_{}, qd_target_{}, qdd_target_{};
  long torque_limited_steps_ = 0;
  double finger_target_ = 0;
  int held_ = -1;
  FailedGrasp failed_grasp_;
  std::optional<world::Footprint> reserved_;
  int gripper_body_ = -1, left_body_ = -1, right_body_ = -1;
  int tcp_site_ = -1, flange_site_ = -1;
  int elbow_body_ = -1;
  std::vector<int> big_capsules_;  // geoms of the upper arm and forearm links
  int finger_qpos_ = 6;
  std::vector<mjtNum> mvec_, mres_;
};

}  // namespace rtamp::sim
