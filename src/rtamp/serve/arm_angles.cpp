#include "rtamp/serve/arm_angles.hpp"

#include "rtamp/sim/mjcf_builder.hpp"

namespace rtamp::serve {

namespace {

robot::Ur5Kinematics::Config config_of(const world::Robot& robot) {
  robot::Ur5Kinematics::Config c;
  c.base = robot::Ur5Kinematics::base_pose(robot);
  return c;
}

}  // namespace

ArmAngles::ArmAngles(const world::Robot& robot) : kin_(config_of(robot)), home_(sim::MjcfOptions{}.home), last_(home_) {}

void ArmAngles::fill(exec::Frame& f) {
  if (f.q) return;
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
  tool.translation() = Eigen::Vector3d(f.tool[0], f.tool[1], f.tool[2]);
  tool.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();  // z down
  const std::optional<robot::Joints> q = kin_.ik_nearest(tool, last_);
  last_ = q ? *q : home_;
  f.q = last_;
}

}  // namespace rtamp::serve
