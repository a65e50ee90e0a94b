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
  // Of the IK solutions, those with the elbow and the wrist above the tool (none
  // through the table or a tray below it), the nearest the last angles.
  robot::IkSolutions all;
  kin_.ik_tool(tool, all, &last_);
  const robot::Joints* best = nullptr;
  double nearest = 0;
  for (const robot::Joints& q : all) {
    const auto frames = kin_.link_frames(q);
    bool above = true;
    for (int k : {2, 3, 4}) above = above && frames[static_cast<std::size_t>(k)].translation().z() > f.tool[2];
    const double d = robot::weighted_distance(q, last_);
    if (above && (!best || d < nearest)) {
      best = &q;
      nearest = d;
    }
  }
  last_ = best ? *best : home_;
  f.q = last_;
}

}  // namespace rtamp::serve
