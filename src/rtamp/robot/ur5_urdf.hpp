// The UR5 as a URDF robot description (what ROS 2 tools draw a robot from:
// `/robot_description`, RViz's RobotModel, Foxglove's URDF layer), written from
// the same kinematics rtamp plans and simulates with (Ur5Kinematics::Config:
// the DH parameters of models/ur5.xml, the joint limits, the tool offset).
// Links PREFIX base, link1..link6, flange, tool; revolute joints named as
// Universal Robots' description names them (shoulder_pan_joint .. wrist_3_joint,
// ur5_joint_names()), joint k in link k-1 at (a_{k-1}, 0, d_{k-1}) turned by
// alpha_{k-1} about x, rotating about z — so that base * link6 * flange is
// Ur5Kinematics::flange_pose and the tool is the flange moved tool_offset along z.
// Each link is drawn as a cylinder along its DH segment and a joint housing.
#pragma once

#include <array>
#include <string>

#include "rtamp/robot/ur5_kinematics.hpp"

namespace rtamp::robot {

// shoulder_pan_joint, shoulder_lift_joint, elbow_joint, wrist_1_joint, wrist_2_joint, wrist_3_joint.
const std::array<const char*, kDof>& ur5_joint_names();

// The URDF text (robot name "ur5"); link names start with `prefix` (e.g. "ur5/").
// The base pose is not in it: the base link is where a parent frame puts it.
std::string ur5_urdf(const Ur5Kinematics::Config& config, const std::string& prefix = "ur5/");

// The fixed part of joint k (1..6) in its parent link, and of the flange (k = 7) in link6:
// translation (a_{k-1}, 0, d_{k-1}), rotation alpha_{k-1} about x (identity for k = 1).
Eigen::Isometry3d ur5_joint_origin(const DhParameters& dh, int k);

}  // namespace rtamp::robot
