// The paper's skill library (Section III-B, Fig. 2 "skill library"): pick(o) and
// place(o, spot) as PLANS of motion, independent of any simulator. A plan is the
// joint trajectory the arm would run, the gripper events on it, and its motion
// cost = end-effector (tool point) path length of that trajectory.
//
// Skill structure (top-down grasps: tool z points down, tool yaw aligned with the
// thing, fingers close along tool y):
//   pick : transit (joint space; around obstacles with OMPL if a checker is given)
//          to the pre-grasp pose `approach_height` above the grasp point → straight
//          approach down → dwell `gripper_seconds` with a Close event at its start →
//          straight retreat up (the approach reversed).
//   place: the same to the place pose (thing's target pose ∘ grasp), Open event.
// Candidates: every tool yaw thing_yaw + grasp.yaw + k·2π/grasp.yaw_symmetry and
// every IK solution of the pre-grasp pose, tried in order of weighted joint distance
// from the start; the first whose pre-grasp configuration is collision-free, whose
// straight approach succeeds, and whose transit can be planned is used.
// Only the transit is collision-checked: the approach and retreat end in intended
// contact (fingers around the thing, a held thing on its support); the checker's
// implementation decides what it ignores there (see sim layer). If the start
// configuration itself collides (the arm was stopped in contact), the plan first
// backs the tool straight up by `approach_height`, unchecked, and transits from there.
// Invariants of an ok plan: trajectory.start() == q0; cost == tool_path_length(trajectory);
// events are inside [0, duration]; end == trajectory.end().
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "rtamp/robot/collision_checker.hpp"
#include "rtamp/robot/motion_planner.hpp"
#include "rtamp/robot/trajectory.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::robot {

// A thing's pose on the table: the centre of its base and its yaw about world z.
struct ThingPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0;
};

// How the tool holds a thing, in the thing's frame (origin at its base centre, yawed).
struct Grasp {
  Eigen::Vector3d offset{0, 0, 0.02};  // tool point in the thing's frame
  double yaw = 0;                      // tool yaw relative to the thing's yaw
  int yaw_symmetry = 4;                // grasp equally good after tool turns of 2π/n
  // A block: fingers around its middle; 4-fold if its footprint is square, else 2-fold.
  static Grasp block(const world::Vec3& size);
  // A tray: fingers straddling the middle of its rim on the +x side (rim `rim` thick,
  // `depth` below the rim top), closing along the tray's x axis.
  static Grasp tray(const world::Vec3& size, double rim = 0.008, double depth = 0.01);
};

struct SkillOptions {
  double approach_height = 0.10;  // m above the grasp point where the straight approach starts
  double gripper_seconds = 0.3;   // dwell while the fingers close / open
  MotionLimits limits;
  CartesianOptions cartesian;
  PlannerOptions planner;
  Joints weights = kDefaultJointWeights;
  double cost_joint_step = 0.01;  // rad: sampling of the tool path length
};

struct GripperEvent {
  enum class Kind { Close, Open };
  Kind kind = Kind::Close;
  double time = 0;  // s from the start of the skill's trajectory
};

struct SkillPlan {
  bool ok = false;
  std::string why;  // failure reason
  Trajectory trajectory;
  std::vector<GripperEvent> events;
  double cost = 0;        // tool path length, metres
  double tool_yaw = 0;    // world yaw of the tool at the grasp / place pose
  double grasp_yaw = 0;   // tool yaw relative to the thing (pick: choose; place: pass it on)
  Joints end{};           // final configuration
  bool planned_around = false;  // transit needed OMPL
  double t_transit = 0, t_approach = 0, t_gripper = 0;  // phase end times
};

// Tool pose of a top-down grasp at `point` with world tool yaw `yaw`.
Eigen::Isometry3d top_down_pose(const Eigen::Vector3d& point, double yaw);

SkillPlan plan_pick(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& thing, const Grasp& grasp,
                    const SkillOptions& options = {}, CollisionChecker* checker = nullptr);
// `grasp.yaw` must be the relative yaw the pick chose (SkillPlan::grasp_yaw); the place
// may still turn the thing by multiples of 2π/yaw_symmetry (it looks the same).
SkillPlan plan_place(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& target, const Grasp& grasp,
                     const SkillOptions& options = {}, CollisionChecker* checker = nullptr);

// pick then place as one plan (cost = sum; events of both).
SkillPlan plan_pick_and_place(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& thing,
                              const ThingPose& target, const Grasp& grasp, const SkillOptions& options = {},
                              CollisionChecker* pick_checker = nullptr, CollisionChecker* place_checker = nullptr);

}  // namespace rtamp::robot
