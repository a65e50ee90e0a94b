// UR5 kinematics: forward kinematics (all link frames, flange, gripper tool
// frame) and closed-form inverse kinematics returning every solution (up to 8)
// from the published standard Denavit–Hartenberg parameters. This is the
// geometry behind the paper's "motion cost computed by inverse kinematics"
// (Section III-B) and the skill library.
//
// Conventions (docs/robot.md has the full table):
//  - Standard DH: A_i = Rz(θ_i) · Tz(d_i) · Tx(a_i) · Rx(α_i); flange = A_1 ··· A_6.
//  - The robot's base frame is DH frame 0 (z up along joint 1, at the mounting
//    plate); it sits in the world at `base` (world::Robot base position + yaw).
//  - The tool frame (parallel gripper, fingertip centre) is the flange frame
//    translated by `tool_offset` along the flange z axis; fingers close along tool y.
//  - IK branches: shoulder (θ1: 2) × wrist (θ5 = ±acos: 2) × elbow (θ3 = ±acos: 2).
//    At the wrist singularity (sin θ5 = 0) θ4 and θ6 are coupled; θ6 is then taken
//    from the reference configuration (or 0). Coincident branches (shoulder /
//    elbow / wrist singular) are reported once. No solution is ever NaN.
// Invariants: every IK solution is inside `limits`, reproduces the requested pose
// (verified by FK: position error < 1e-7 m, rotation error < 1e-7), and solutions
// are pairwise distinct (mod 2π). Only the UR structure (α = [π/2,0,0,π/2,−π/2,0],
// d2 = d3 = 0, a1 = a4 = a5 = a6 = 0) is supported by the IK (UR3/UR5/UR10 share it).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>

#include "rtamp/robot/joints.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::robot {

struct DhParameters {
  std::array<double, kDof> d{};
  std::array<double, kDof> a{};
  std::array<double, kDof> alpha{};
  // UR5 (Universal Robots' published values, metres / radians), read at build time from
  // the model file models/ur5.xml, the one place they are written.
  static DhParameters ur5();
};

// The UR5's joint velocity limits (rad/s; 180°/s on every joint, from models/ur5.xml).
Joints ur5_velocity_limits();

// All solutions of one IK query; fixed capacity, no allocation.
struct IkSolutions {
  std::array<Joints, 8> q{};
  int count = 0;
  bool empty() const { return count == 0; }
  const Joints* begin() const { return q.data(); }
  const Joints* end() const { return q.data() + count; }
  const Joints& operator[](int i) const { return q[static_cast<std::size_t>(i)]; }
};

class Ur5Kinematics {
 public:
  struct Config {
    DhParameters dh = DhParameters::ur5();
    double tool_offset = 0.15;  // flange → fingertip centre along flange z, metres
    JointLimits limits = JointLimits::ur5();
    Eigen::Isometry3d base = Eigen::Isometry3d::Identity();  // robot base frame in the world
  };

  Ur5Kinematics();
  explicit Ur5Kinematics(Config config);

  // Base pose of a scenario's robot: translation `base`, rotation `yaw` about world z.
  static Eigen::Isometry3d base_pose(const world::Robot& robot);

  const Config& config() const { return config_; }
  const JointLimits& limits() const { return config_.limits; }
  const Eigen::Isometry3d& base() const { return config_.base; }
  double tool_offset() const { return config_.tool_offset; }

  // One DH transform A_i(θ).
  Eigen::Isometry3d dh_transform(int i, double theta) const;

  // Forward kinematics, world frame.
  Eigen::Isometry3d flange_pose(const Joints& q) const;
  Eigen::Isometry3d tool_pose(const Joints& q) const;
  Eigen::Vector3d tool_point(const Joints& q) const;
  // Frames 0..6 (frame 0 = base, frame 6 = flange), world frame.
  std::array<Eigen::Isometry3d, kDof + 1> link_frames(const Joints& q) const;

  // Inverse kinematics, world frame. Each returned joint angle is the 2π-equivalent
  // inside the limits nearest `near` (nearest 0 when near is null). Returns the count.
  int ik_flange(const Eigen::Isometry3d& flange_world, IkSolutions& out, const Joints* near = nullptr) const;
  int ik_tool(const Eigen::Isometry3d& tool_world, IkSolutions& out, const Joints* near = nullptr) const;

  // The solution nearest `near` in weighted joint distance; nullopt if unreachable.
  std::optional<Joints> ik_nearest(const Eigen::Isometry3d& tool_world, const Joints& near,
                                   const Joints& weights = kDefaultJointWeights) const;

  // Flange pose that puts the tool frame at tool_world.
  Eigen::Isometry3d flange_for_tool(const Eigen::Isometry3d& tool_world) const;

 private:
  void ik_base(const Eigen::Isometry3d& t06, IkSolutions& out, const Joints* near) const;

  Config config_;
  Eigen::Isometry3d base_inv_;
  Eigen::Isometry3d tool_;      // flange → tool
  Eigen::Isometry3d tool_inv_;  // tool → flange
  std::array<double, kDof> cos_alpha_{}, sin_alpha_{};
};

// Position and rotation-angle error between two poses (rotation: angle of R_a^T R_b).
double position_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double rotation_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

}  // namespace rtamp::robot
