// The UR5's URDF (robot/ur5_urdf.hpp) against rtamp's own kinematics: its joint
// chain, read back from the text (origins, axes, limits), composed at random joint
// angles gives Ur5Kinematics' flange and tool poses; the joints are UR's names.
#include <gtest/gtest.h>

#include <random>
#include <regex>

#include "rtamp/robot/ur5_urdf.hpp"

namespace rtamp::robot {
namespace {

struct UrdfJoint {
  std::string name, type, parent, child;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  double lower = 0, upper = 0;
};

std::vector<UrdfJoint> joints_of(const std::string& urdf) {
  std::vector<UrdfJoint> out;
  const std::regex joint(R"re(<joint name="([^"]+)" type="(\w+)">\s*<parent link="([^"]+)"/>\s*<child link="([^"]+)"/>\s*<origin xyz="([^"]+)" rpy="([^"]+)"/>([\s\S]*?)</joint>)re");
  for (auto it = std::sregex_iterator(urdf.begin(), urdf.end(), joint); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    UrdfJoint j{m[1], m[2], m[3], m[4]};
    double x, y, z, r, p, yaw;
    std::istringstream(m[5]) >> x >> y >> z;
    std::istringstream(m[6]) >> r >> p >> yaw;
    j.origin.translation() = Eigen::Vector3d(x, y, z);
    j.origin.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(p, Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(r, Eigen::Vector3d::UnitX()))
                            .toRotationMatrix();
    std::smatch lim;
    const std::string rest = m[7];
    if (std::regex_search(rest, lim, std::regex(R"re(<axis xyz="0 0 1"/>\s*<limit lower="([^"]+)" upper="([^"]+)")re"))) {
      j.lower = std::stod(lim[1]);
      j.upper = std::stod(lim[2]);
    }
    out.push_back(j);
  }
  return out;
}

TEST(Ur5Urdf, ItsChainIsTheKinematicsOfTheRobotLayer) {
  Ur5Kinematics::Config config;
  const Ur5Kinematics kin(config);
  const auto joints = joints_of(ur5_urdf(config));
  ASSERT_EQ(joints.size(), 8u);  // six revolute, flange, tool
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(joints[i].name, ur5_joint_names()[i]);
    EXPECT_EQ(joints[i].type, "revolute");
    EXPECT_EQ(joints[i].parent, i == 0 ? "ur5/base" : "ur5/link" + std::to_string(i));
    EXPECT_EQ(joints[i].child, "ur5/link" + std::to_string(i + 1));
    EXPECT_NEAR(joints[i].lower, config.limits.lower[i], 1e-8);
    EXPECT_NEAR(joints[i].upper, config.limits.upper[i], 1e-8);
  }
  EXPECT_EQ(joints[6].child, "ur5/flange");
  EXPECT_EQ(joints[7].child, "ur5/tool");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-3, 3);
  for (int trial = 0; trial < 50; ++trial) {
    Joints q;
    for (double& a : q) a = angle(rng);
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    for (std::size_t i = 0; i < 6; ++i) t = t * joints[i].origin * Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ());
    const Eigen::Isometry3d flange = t * joints[6].origin, tool = flange * joints[7].origin;
    EXPECT_LT((flange.matrix() - kin.flange_pose(q).matrix()).norm(), 1e-7);
    EXPECT_LT((tool.matrix() - kin.tool_pose(q).matrix()).norm(), 1e-7);
  }
}

}  // namespace
}  // namespace rtamp::robot
