// The UR5's model file (models/ur5.xml, compiled into the sim library) read back by
// MuJoCo: (1) its kinematics equal robot::Ur5Kinematics (whose DH parameters are generated
// from the same file) on random configurations; (2) every link's mass, centre of mass and
// inertia tensor equal the values Universal Robots publish, compared in the world frame
// through the description's own joint chain (an independent oracle for the frame
// conversion the file's header describes); (3) joint ranges, velocity and effort limits
// are the published ones, in the file alone and in a scenario's world.
// Published values: Universal_Robots_ROS2_Description at 2221ec0f720fb1af99339eb891639b499b62f1da,
// config/ur5/{physical_parameters,joint_limits,default_kinematics}.yaml.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cstring>
#include <memory>
#include <numbers>
#include <random>
#include <string>

#include "rtamp/robot/trajectory.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/sim/simulation.hpp"
#include "rtamp/sim/ur5_model.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

constexpr double kPi = std::numbers::pi;

struct Loaded {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  Loaded() {
    const std::string_view text = ur5_model_mjcf();
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    EXPECT_EQ(mj_makeEmptyFileVFS(&vfs, "ur5.xml", static_cast<int>(text.size())), 0);
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "ur5.xml")], text.data(), text.size());
    char err[1000] = "";
    m = mj_loadXML("ur5.xml", &vfs, err, sizeof err);
    mj_deleteVFS(&vfs);
    EXPECT_NE(m, nullptr) << err;
    if (m) d = mj_makeData(m);
  }
  ~Loaded() {
    if (d) mj_deleteData(d);
    if (m) mj_deleteModel(m);
  }
  int body(const std::string& n) const { return mj_name2id(m, mjOBJ_BODY, n.c_str()); }
};

Eigen::Matrix3d rpy(double r, double p, double y) {  // URDF: fixed axes x, y, z = Rz Ry Rx
  return (Eigen::AngleAxisd(y, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(p, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(r, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d origin(double x, double y, double z, double r, double p, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  t.linear() = rpy(r, p, yaw);
  return t;
}

// One link of the published description: its joint origin in the parent link
// (default_kinematics.yaml, exact DH values for the calibration's 1e-11 residues), and
// its inertial (physical_parameters.yaml).
struct PublishedLink {
  Eigen::Isometry3d joint_origin;
  double mass;
  Eigen::Vector3d cog;
  Eigen::Vector3d inertia_rpy;
  Eigen::Vector3d diag_inertia;  // ixx, iyy, izz (the published tensors are diagonal)
};

std::array<PublishedLink, 6> published() {
  return {{
      {origin(0, 0, 0.089159, 0, 0, 0), 3.7, {0.0, -0.00193, -0.02561}, {0, 0, 0},
       {0.014972358333333331, 0.014972358333333331, 0.01040625}},
      {origin(0, 0, 0, kPi / 2, 0, 0), 8.393, {-0.2125, 0.0, 0.11336}, {0, kPi / 2, 0},
       {0.13388583541666665, 0.13388583541666665, 0.0151074}},
      {origin(-0.425, 0, 0, 0, 0, 0), 2.33, {-0.24225, 0.0, 0.0265}, {0, kPi / 2, 0},
       {0.031216803515624995, 0.031216803515624995, 0.004095}},
      {origin(-0.39225, 0, 0.10915, 0, 0, 0), 1.219, {0.0, -0.01634, -0.0018}, {0, 0, 0},
       {0.002013889583333333, 0.002013889583333333, 0.0021942}},
      {origin(0, -0.09465, 0, kPi / 2, 0, 0), 1.219, {0.0, 0.01634, -0.0018}, {0, 0, 0},
       {0.0018310395833333333, 0.0018310395833333333, 0.0021942}},
      {origin(0, 0.0823, 0, kPi / 2, kPi, kPi), 0.1879, {0.0, 0.0, -0.001159}, {0, 0, 0},
       {8.062475833333332e-05, 8.062475833333332e-05, 0.0001321171875}},
  }};
}

robot::Joints random_q(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-kPi, kPi);
  robot::Joints q;
  for (double& v : q) v = u(rng);
  return q;
}

void set_q(const Loaded& l, const robot::Joints& q) {
  for (int j = 0; j < 6; ++j) l.d->qpos[l.m->jnt_qposadr[j]] = q[static_cast<std::size_t>(j)];
  mj_kinematics(l.m, l.d);
}

TEST(Ur5Model, LoadsAloneWithSixHingesAndActuators) {
  Loaded l;
  ASSERT_NE(l.m, nullptr);
  EXPECT_EQ(l.m->njnt, 6);
  EXPECT_EQ(l.m->nu, 6);
  for (int j = 0; j < 6; ++j) {
    EXPECT_EQ(l.m->jnt_type[j], mjJNT_HINGE);
    EXPECT_EQ(std::string(mj_id2name(l.m, mjOBJ_JOINT, j)), "ur5:joint" + std::to_string(j + 1));
    EXPECT_EQ(l.m->actuator_trnid[2 * j], j);
  }
}

TEST(Ur5Model, ForwardKinematicsEqualsRobotLayer) {
  Loaded l;
  ASSERT_NE(l.m, nullptr);
  const robot::Ur5Kinematics arm;  // base at the origin, DH from the same file
  const int flange = mj_name2id(l.m, mjOBJ_SITE, "flange");
  ASSERT_GE(flange, 0);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 500; ++k) {
    const robot::Joints q = random_q(rng);
    set_q(l, q);
    const Eigen::Isometry3d want = arm.flange_pose(q);
    const Eigen::Vector3d p(l.d->site_xpos[3 * flange], l.d->site_xpos[3 * flange + 1], l.d->site_xpos[3 * flange + 2]);
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r(i, j) = l.d->site_xmat[9 * flange + 3 * i + j];
    EXPECT_LT((p - want.translation()).norm(), 1e-6);
    EXPECT_LT((r - want.linear()).norm(), 1e-6);
    // Every DH frame: body ur5:link<i+1> is DH frame i turned by θ_{i+1}.
    const auto frames = arm.link_frames(q);
    for (int i = 0; i < 6; ++i) {
      const int b = l.body("ur5:link" + std::to_string(i + 1));
      const Eigen::Vector3d bp(l.d->xpos[3 * b], l.d->xpos[3 * b + 1], l.d->xpos[3 * b + 2]);
      EXPECT_LT((bp - frames[static_cast<std::size_t>(i)].translation()).norm(), 1e-6) << "link " << i + 1;
    }
  }
}

TEST(Ur5Model, InertialsArePublishedOnesInTheWorldFrame) {
  Loaded l;
  ASSERT_NE(l.m, nullptr);
  const auto links = published();
  double total = 0;
  for (const auto& p : links) total += p.mass;
  EXPECT_NEAR(total, 17.0489, 1e-12);
  EXPECT_NEAR(l.m->body_subtreemass[l.body("ur5:link1")], total, 1e-9);
  std::mt19937_64 rng(11);
  for (int k = 0; k < 50; ++k) {
    const robot::Joints q = random_q(rng);
    set_q(l, q);
    // The description's chain: link i = link i-1 · joint origin · Rz(q_i), from its base.
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    for (int i = 0; i < 6; ++i) {
      const auto& p = links[static_cast<std::size_t>(i)];
      t = t * p.joint_origin * Eigen::AngleAxisd(q[static_cast<std::size_t>(i)], Eigen::Vector3d::UnitZ());
      const int b = l.body("ur5:link" + std::to_string(i + 1));
      ASSERT_GE(b, 0);
      EXPECT_NEAR(l.m->body_mass[b], p.mass, 1e-12) << "link " << i + 1;
      const Eigen::Vector3d com_want = t * p.cog;
      const Eigen::Vector3d com(l.d->xipos[3 * b], l.d->xipos[3 * b + 1], l.d->xipos[3 * b + 2]);
      EXPECT_LT((com - com_want).norm(), 1e-6) << "link " << i + 1;
      const Eigen::Matrix3d ri = t.linear() * rpy(p.inertia_rpy[0], p.inertia_rpy[1], p.inertia_rpy[2]);
      const Eigen::Matrix3d i_want = ri * p.diag_inertia.asDiagonal() * ri.transpose();
      Eigen::Matrix3d xi;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) xi(r, c) = l.d->ximat[9 * b + 3 * r + c];
      const Eigen::Vector3d diag(l.m->body_inertia[3 * b], l.m->body_inertia[3 * b + 1], l.m->body_inertia[3 * b + 2]);
      const Eigen::Matrix3d i_got = xi * diag.asDiagonal() * xi.transpose();
      EXPECT_LT((i_got - i_want).norm(), 1e-9) << "link " << i + 1;
    }
  }
}

TEST(Ur5Model, LimitsArePublishedOnes) {
  Loaded l;
  ASSERT_NE(l.m, nullptr);
  const robot::JointLimits lim = robot::JointLimits::ur5();
  const double range[6] = {2 * kPi, 2 * kPi, kPi, 2 * kPi, 2 * kPi, 2 * kPi};
  const double effort[6] = {150, 150, 150, 28, 28, 28};
  const int vel = mj_name2id(l.m, mjOBJ_NUMERIC, "ur5:velocity_limit");
  ASSERT_GE(vel, 0);
  ASSERT_EQ(l.m->numeric_size[vel], 6);
  const robot::Joints vlim = robot::ur5_velocity_limits();
  const robot::MotionLimits traj;
  for (int j = 0; j < 6; ++j) {
    EXPECT_EQ(l.m->jnt_limited[j], 1);
    EXPECT_NEAR(l.m->jnt_range[2 * j], -range[j], 1e-12) << j;
    EXPECT_NEAR(l.m->jnt_range[2 * j + 1], range[j], 1e-12) << j;
    EXPECT_EQ(lim.lower[j], l.m->jnt_range[2 * j]) << j;
    EXPECT_EQ(lim.upper[j], l.m->jnt_range[2 * j + 1]) << j;
    EXPECT_EQ(l.m->actuator_forcelimited[j], 1) << j;
    EXPECT_EQ(l.m->actuator_forcerange[2 * j], -effort[j]) << j;
    EXPECT_EQ(l.m->actuator_forcerange[2 * j + 1], effort[j]) << j;
    const double v = l.m->numeric_data[l.m->numeric_adr[vel] + j];
    EXPECT_NEAR(v, kPi, 1e-12) << j;  // 180°/s
    EXPECT_EQ(vlim[j], v) << j;
    EXPECT_LE(traj.vmax[j], v) << j;  // the skills never plan faster than the arm can move
  }
}

TEST(Ur5Model, ScenarioWorldKeepsTheModelsValues) {
  Simulation sim(testing::three_block(true));
  const mjModel* m = sim.model();
  Loaded l;
  ASSERT_NE(l.m, nullptr);
  for (int j = 0; j < 6; ++j) {
    EXPECT_EQ(m->jnt_range[2 * j], l.m->jnt_range[2 * j]);
    EXPECT_EQ(m->jnt_range[2 * j + 1], l.m->jnt_range[2 * j + 1]);
    EXPECT_EQ(m->actuator_forcerange[2 * j + 1], l.m->actuator_forcerange[2 * j + 1]);
    EXPECT_EQ(m->actuator_gainprm[mjNGAIN * j], l.m->actuator_gainprm[mjNGAIN * j]);
    const std::string link = "ur5:link" + std::to_string(j + 1);
    EXPECT_EQ(m->body_mass[mj_name2id(m, mjOBJ_BODY, link.c_str())], l.m->body_mass[l.body(link)]);
  }
  EXPECT_GE(mj_name2id(m, mjOBJ_NUMERIC, "ur5:velocity_limit"), 0);
}

}  // namespace
}  // namespace rtamp::sim
