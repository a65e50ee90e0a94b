// Joint-space trajectories with a time parametrisation under per-joint velocity
// and acceleration limits, Cartesian straight lines for approach and retreat,
// and the end-effector path length that the paper uses as motion cost
// (Section III-B: "the incremental displacement of a robot's end effector").
//
// Parametrisation (docs/robot.md): a trajectory is a sequence of pieces. A piece
// is a polyline of joint waypoints w_0..w_n followed at a common path parameter
// u ∈ [0, n] (q(u) linear between w_i and w_{i+1}), and u(t) is a trapezoidal
// profile (rest to rest; triangular when too short to reach cruise speed):
//   u̇ ≤ min_{i,j} vmax_j / |Δw_ij|,  |ü| ≤ min_{i,j} amax_j / |Δw_ij|,
// so every joint respects its limits inside each polyline interval and all joints
// start and stop together (synchronised). A joint-space path of k waypoints is
// k−1 two-point pieces (the arm stops at each waypoint); a Cartesian line is one
// piece through its dense IK samples (the velocity direction turns at the samples;
// with 5 mm samples these turns are small — the only place where the limits hold
// per interval rather than exactly). A dwell piece holds still for a duration.
// Invariants: piece start times are increasing and contiguous; sample(t) clamps t
// to [0, duration()]; q is continuous in t; q̇ is zero at piece boundaries.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/robot/joints.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"

namespace rtamp::robot {

struct MotionLimits {
  Joints vmax{1.0, 1.0, 1.0, 1.5, 1.5, 1.5};  // rad/s (UR5: π, robot::ur5_velocity_limits())
  Joints amax{2.0, 2.0, 2.0, 3.0, 3.0, 3.0};  // rad/s²
};

// Rest-to-rest trapezoidal profile over a distance D ≥ 0 with speed ≤ v, accel ≤ a.
struct TrapezoidProfile {
  double distance = 0, vpeak = 0, accel = 0, t_acc = 0, t_cruise = 0;
  static TrapezoidProfile make(double distance, double vmax, double amax);
  double duration() const { return 2 * t_acc + t_cruise; }
  // Position and velocity at time t (clamped to [0, duration()]).
  void eval(double t, double& s, double& sd) const;
};

class Trajectory {
 public:
  struct Sample {
    Joints q{};
    Joints qd{};
  };
  struct Piece {
    double t0 = 0;
    std::size_t first = 0, count = 0;  // waypoints [first, first + count) in waypoints()
    TrapezoidProfile profile;          // over u ∈ [0, count − 1]; for a dwell: duration only
    double dwell = 0;                  // > 0 for a dwell piece (count == 1)
    double duration() const { return dwell > 0 ? dwell : profile.duration(); }
  };

  Trajectory() = default;
  explicit Trajectory(const Joints& start) { waypoints_.push_back(start); }

  bool empty() const { return waypoints_.empty(); }
  double duration() const { return duration_; }
  const Joints& start() const { return waypoints_.front(); }
  const Joints& end() const { return waypoints_.back(); }
  const std::vector<Piece>& pieces() const { return pieces_; }
  const std::vector<Joints>& waypoints() const { return waypoints_; }

  // Appends moves that begin at end() (the first waypoint given must equal end()
  // within 1e-9 rad, or the trajectory must be empty). Returns the end time.
  double append_joint_path(const std::vector<Joints>& path, const MotionLimits& limits);  // stops at each
  double append_polyline(const std::vector<Joints>& path, const MotionLimits& limits);   // one profile
  double append_dwell(double seconds);
  // Appends another trajectory (its start must equal end()), shifting its times.
  double append(const Trajectory& other);

  Sample sample(double t) const;

 private:
  void check_start(const Joints& first) const;
  std::vector<Joints> waypoints_;
  std::vector<Piece> pieces_;
  double duration_ = 0;
};

// Straight tool motion from FK(q_start) to `goal` (world frame): position linear,
// orientation slerped, `step` metres / `angle_step` radians apart at most; each sample
// solved by IK nearest the previous configuration. Fails (nullopt, `why` set) if a
// sample is unreachable or a joint moves more than `max_joint_jump` between samples
// (a branch switch, e.g. through the wrist singularity). The result starts with q_start.
struct CartesianOptions {
  double step = 0.005;
  double angle_step = 0.05;
  double max_joint_jump = 0.15;
  Joints weights = kDefaultJointWeights;
};
std::optional<std::vector<Joints>> cartesian_line(const Ur5Kinematics& arm, const Joints& q_start,
                                                  const Eigen::Isometry3d& goal, const CartesianOptions& options,
                                                  std::string* why = nullptr);

// End-effector (tool point) path length: Σ |Δ tool point| over the waypoint polylines,
// each interval subdivided so that no joint moves more than `max_joint_step` per sample.
double tool_path_length(const Ur5Kinematics& arm, const std::vector<Joints>& path, double max_joint_step = 0.01);
double tool_path_length(const Ur5Kinematics& arm, const Trajectory& trajectory, double max_joint_step = 0.01);

}  // namespace rtamp::robot
