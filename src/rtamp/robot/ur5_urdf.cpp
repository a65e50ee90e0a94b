#include "rtamp/robot/ur5_urdf.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rtamp::robot {

namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", std::abs(v) < 1e-15 ? 0.0 : v);
  return b;
}

std::string xyz(const Eigen::Vector3d& p) { return num(p.x()) + " " + num(p.y()) + " " + num(p.z()); }

// Roll, pitch, yaw (URDF: R = Rz(yaw) Ry(pitch) Rx(roll)) of a rotation.
std::string rpy(const Eigen::Matrix3d& r) {
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  double roll, yaw;
  if (std::abs(std::cos(pitch)) > 1e-9) {
    roll = std::atan2(r(2, 1), r(2, 2));
    yaw = std::atan2(r(1, 0), r(0, 0));
  } else {  // gimbal lock: yaw 0
    roll = std::atan2(-r(1, 2), r(1, 1));
    yaw = 0;
  }
  return num(roll) + " " + num(pitch) + " " + num(yaw);
}

std::string origin(const Eigen::Isometry3d& t) {
  return "<origin xyz=\"" + xyz(t.translation()) + "\" rpy=\"" + rpy(t.rotation()) + "\"/>";
}

// A cylinder of radius r from the link frame's origin to p (skipped when p is at the origin).
std::string segment(const Eigen::Vector3d& p, double r, const std::string& material) {
  const double length = p.norm();
  if (length < 1e-6) return "";
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = p / 2;
  t.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), p / length).toRotationMatrix();
  return "    <visual>" + origin(t) + "<geometry><cylinder radius=\"" + num(r) + "\" length=\"" + num(length) +
         "\"/></geometry><material name=\"" + material + "\"/></visual>\n";
}

}  // namespace

const std::array<const char*, kDof>& ur5_joint_names() {
  static const std::array<const char*, kDof> names{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                                   "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
  return names;
}

Eigen::Isometry3d ur5_joint_origin(const DhParameters& dh, int k) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (k <= 1) return t;
  const auto i = static_cast<std::size_t>(k - 2);  // the parent's DH row
  t.translation() = Eigen::Vector3d(dh.a[i], 0, dh.d[i]);
  t.linear() = Eigen::AngleAxisd(dh.alpha[i], Eigen::Vector3d::UnitX()).toRotationMatrix();
  return t;
}

std::string ur5_urdf(const Ur5Kinematics::Config& config, const std::string& prefix) {
  // Effort limits as models/ur5.xml's actuator force ranges (N m); velocity limits from it too.
  static const double effort[kDof] = {150, 150, 150, 28, 28, 28};
  const Joints velocity = ur5_velocity_limits();
  std::string o =
      "<?xml version=\"1.0\"?>\n"
      "<!-- The UR5 as rtamp models it (rtamp/robot/ur5_urdf.hpp): standard DH parameters of models/ur5.xml -->\n"
      "<robot name=\"ur5\">\n"
      "  <material name=\"ur5/housing\"><color rgba=\"0.2 0.3 0.55 1\"/></material>\n"
      "  <material name=\"ur5/link\"><color rgba=\"0.5 0.52 0.56 1\"/></material>\n"
      "  <link name=\"" + prefix + "base\">\n"
      "    <visual><origin xyz=\"0 0 0.02\" rpy=\"0 0 0\"/><geometry><cylinder radius=\"0.075\" length=\"0.04\"/>"
      "</geometry><material name=\"ur5/link\"/></visual>\n  </link>\n";
  for (int k = 1; k <= kDof; ++k) {
    const Eigen::Vector3d next = ur5_joint_origin(config.dh, k + 1).translation();
    o += "  <link name=\"" + prefix + "link" + std::to_string(k) + "\">\n";
    o += "    <visual><origin xyz=\"0 0 0\" rpy=\"0 0 0\"/><geometry><cylinder radius=\"0.06\" length=\"0.12\"/>"
         "</geometry><material name=\"ur5/housing\"/></visual>\n";
    o += segment(next, 0.045, "ur5/link");
    o += "  </link>\n";
    const auto j = static_cast<std::size_t>(k - 1);
    o += "  <joint name=\"" + std::string(ur5_joint_names()[j]) + "\" type=\"revolute\">\n    <parent link=\"" + prefix +
         (k == 1 ? std::string("base") : "link" + std::to_string(k - 1)) + "\"/>\n    <child link=\"" + prefix +
         "link" + std::to_string(k) + "\"/>\n    " + origin(ur5_joint_origin(config.dh, k)) +
         "\n    <axis xyz=\"0 0 1\"/>\n    <limit lower=\"" + num(config.limits.lower[j]) + "\" upper=\"" +
         num(config.limits.upper[j]) + "\" effort=\"" + num(effort[j]) + "\" velocity=\"" + num(velocity[j]) +
         "\"/>\n  </joint>\n";
  }
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
  tool.translation() = Eigen::Vector3d(0, 0, config.tool_offset);
  o += "  <link name=\"" + prefix + "flange\">\n" + segment(tool.translation(), 0.03, "ur5/link") + "  </link>\n";
  o += "  <joint name=\"flange_joint\" type=\"fixed\">\n    <parent link=\"" + prefix + "link6\"/>\n    <child link=\"" +
       prefix + "flange\"/>\n    " + origin(ur5_joint_origin(config.dh, kDof + 1)) + "\n  </joint>\n";
  o += "  <link name=\"" + prefix + "tool\"/>\n";
  o += "  <joint name=\"tool_joint\" type=\"fixed\">\n    <parent link=\"" + prefix + "flange\"/>\n    <child link=\"" +
       prefix + "tool\"/>\n    " + origin(tool) + "\n  </joint>\n</robot>\n";
  return o;
}

}  // namespace rtamp::robot
