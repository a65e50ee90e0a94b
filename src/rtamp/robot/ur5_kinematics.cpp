#include "rtamp/robot/ur5_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ur5_parameters.inc"  // generated from models/ur5.xml

namespace rtamp::robot {

namespace {
constexpr double kPi = std::numbers::pi;
// Tolerances of the closed form (see header).
constexpr double kClamp = 1e-9;        // |cos| up to 1 + kClamp is treated as ±1
constexpr double kWristSingular = 1e-10;  // |sin θ5| below this: wrist singular
constexpr double kVerifyPos = 1e-7;
constexpr double kVerifyRot = 1e-7;
constexpr double kDuplicate = 1e-9;

double clamp_unit(double c) { return std::clamp(c, -1.0, 1.0); }
}  // namespace

DhParameters DhParameters::ur5() {
  DhParameters p;
  std::copy(std::begin(detail::kUr5D), std::end(detail::kUr5D), p.d.begin());
  std::copy(std::begin(detail::kUr5A), std::end(detail::kUr5A), p.a.begin());
  std::copy(std::begin(detail::kUr5Alpha), std::end(detail::kUr5Alpha), p.alpha.begin());
  return p;
}

JointLimits JointLimits::ur5() {
  JointLimits l;
  std::copy(std::begin(detail::kUr5Lower), std::end(detail::kUr5Lower), l.lower.begin());
  std::copy(std::begin(detail::kUr5Upper), std::end(detail::kUr5Upper), l.upper.begin());
  return l;
}

Joints ur5_velocity_limits() {
  Joints v;
  std::copy(std::begin(detail::kUr5VelocityLimit), std::end(detail::kUr5VelocityLimit), v.begin());
  return v;
}

double position_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

double rotation_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  // ||R_a − R_b||_F = 2√2 sin(θ/2): accurate for small θ (unlike acos of the trace).
  const double f = (a.linear() - b.linear()).norm() / (2.0 * std::numbers::sqrt2);
  return 2.0 * std::asin(std::min(1.0, f));
}

Ur5Kinematics::Ur5Kinematics() : Ur5Kinematics(Config{}) {}

Ur5Kinematics::Ur5Kinematics(Config config) : config_(std::move(config)) {
  base_inv_ = config_.base.inverse(Eigen::Isometry);
  tool_ = Eigen::Isometry3d::Identity();
  tool_.translation() = Eigen::Vector3d(0, 0, config_.tool_offset);
  tool_inv_ = tool_.inverse(Eigen::Isometry);
  for (std::size_t k = 0; k < kDof; ++k) {
    cos_alpha_[k] = std::cos(config_.dh.alpha[k]);
    sin_alpha_[k] = std::sin(config_.dh.alpha[k]);
    // Exact zeros for the right angles of the UR table (cos(π/2) is 6e-17 otherwise).
    if (std::abs(cos_alpha_[k]) < 1e-15) cos_alpha_[k] = 0;
    if (std::abs(sin_alpha_[k]) < 1e-15) sin_alpha_[k] = 0;
  }
}

Eigen::Isometry3d Ur5Kinematics::base_pose(const world::Robot& robot) {
  Eigen::Isometry3d b = Eigen::Isometry3d::Identity();
  b.translation() = Eigen::Vector3d(robot.base[0], robot.base[1], robot.base[2]);
  b.linear() = Eigen::AngleAxisd(robot.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return b;
}

Eigen::Isometry3d Ur5Kinematics::dh_transform(int i, double theta) const {
  const auto k = static_cast<std::size_t>(i);
  const double ct = std::cos(theta), st = std::sin(theta);
  const double ca = cos_alpha_[k], sa = sin_alpha_[k];
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  auto& r = t.matrix();
  r(0, 0) = ct;
  r(0, 1) = -st * ca;
  r(0, 2) = st * sa;
  r(0, 3) = config_.dh.a[k] * ct;
  r(1, 0) = st;
  r(1, 1) = ct * ca;
  r(1, 2) = -ct * sa;
  r(1, 3) = config_.dh.a[k] * st;
  r(2, 0) = 0;
  r(2, 1) = sa;
  r(2, 2) = ca;
  r(2, 3) = config_.dh.d[k];
  return t;
}

Eigen::Isometry3d Ur5Kinematics::flange_pose(const Joints& q) const {
  Eigen::Isometry3d t = config_.base;
  for (int i = 0; i < kDof; ++i) t = t * dh_transform(i, q[static_cast<std::size_t>(i)]);
  return t;
}

Eigen::Isometry3d Ur5Kinematics::tool_pose(const Joints& q) const { return flange_pose(q) * tool_; }

Eigen::Vector3d Ur5Kinematics::tool_point(const Joints& q) const {
  const Eigen::Isometry3d f = flange_pose(q);
  return f.translation() + config_.tool_offset * f.linear().col(2);
}

std::array<Eigen::Isometry3d, kDof + 1> Ur5Kinematics::link_frames(const Joints& q) const {
  std::array<Eigen::Isometry3d, kDof + 1> frames;
  frames[0] = config_.base;
  for (int i = 0; i < kDof; ++i) {
    const auto k = static_cast<std::size_t>(i);
    frames[k + 1] = frames[k] * dh_transform(i, q[k]);
  }
  return frames;
}

Eigen::Isometry3d Ur5Kinematics::flange_for_tool(const Eigen::Isometry3d& tool_world) const {
  return tool_world * tool_inv_;
}

int Ur5Kinematics::ik_tool(const Eigen::Isometry3d& tool_world, IkSolutions& out, const Joints* near) const {
  return ik_flange(tool_world * tool_inv_, out, near);
}

int Ur5Kinematics::ik_flange(const Eigen::Isometry3d& flange_world, IkSolutions& out, const Joints* near) const {
  out.count = 0;
  if (!flange_world.matrix().allFinite()) return 0;
  ik_base(base_inv_ * flange_world, out, near);
  return out.count;
}

// Closed form for the UR structure (derivation in docs/robot.md):
//   θ1 from the wrist centre p5 = p6 − d6 z6 (its distance from the plane of joints 2–4 is d4);
//   θ5 from the flange's offset along that plane's normal n = (s1, −c1, 0);
//   θ6 from the base x/y axes seen in the flange frame; θ3, θ2 as a planar 2R arm; θ4 from the rest.
void Ur5Kinematics::ik_base(const Eigen::Isometry3d& t06, IkSolutions& out, const Joints* near) const {
  const auto& dh = config_.dh;
  const double d4 = dh.d[3], d6 = dh.d[5], a2 = dh.a[1], a3 = dh.a[2];
  const Eigen::Matrix3d& r = t06.linear();
  const Eigen::Vector3d p6 = t06.translation();
  const Eigen::Vector3d x6 = r.col(0), y6 = r.col(1), z6 = r.col(2);
  const Eigen::Vector3d p5 = p6 - d6 * z6;

  const double rxy = std::hypot(p5.x(), p5.y());
  if (rxy < std::abs(d4) * (1 - kClamp) || rxy == 0.0) return;  // wrist centre too close to joint 1's axis
  const double phi = std::atan2(p5.y(), p5.x());
  const double psi = std::asin(clamp_unit(d4 / rxy));
  const double theta1s[2] = {phi + psi, phi + kPi - psi};

  const Joints zero{};
  const Joints& ref = near ? *near : zero;

  for (double t1 : theta1s) {
    const double s1 = std::sin(t1), c1 = std::cos(t1);
    const double c5 = (p6.x() * s1 - p6.y() * c1 - d4) / d6;
    if (std::abs(c5) > 1 + kClamp) continue;
    // sin θ5 from the rotation (xn = s5 c6, yn = −s5 s6): exact near the singularity,
    // where acos(c5) would lose half the digits.
    const double xn = x6.x() * s1 - x6.y() * c1;
    const double yn = y6.x() * s1 - y6.y() * c1;
    const double s5abs = std::hypot(xn, yn);
    for (double sign : {1.0, -1.0}) {
      const double s5 = sign * s5abs;
      const double t5 = std::atan2(s5, clamp_unit(c5));
      const bool wrist_singular = s5abs < kWristSingular;
      // At the singularity θ4 and θ6 are coupled: keep θ6 where it is if the elbow allows.
      double t6 = wrist_singular ? ref[5] : std::atan2(-sign * yn, sign * xn);
      const Eigen::Isometry3d a1_inv_t = dh_transform(0, t1).inverse(Eigen::Isometry) * t06;
      const Eigen::Isometry3d a5_inv = dh_transform(4, t5).inverse(Eigen::Isometry);
      auto t14_of = [&](double th6) {
        return Eigen::Isometry3d(a1_inv_t * dh_transform(5, th6).inverse(Eigen::Isometry) * a5_inv);
      };
      auto c3_of = [&](const Eigen::Vector3d& p13) {
        return (p13.x() * p13.x() + p13.y() * p13.y() - a2 * a2 - a3 * a3) / (2 * a2 * a3);
      };
      Eigen::Isometry3d t14 = t14_of(t6);
      Eigen::Vector3d p13 = t14 * Eigen::Vector3d(0, -d4, 0);
      double c3 = c3_of(p13);
      if (std::abs(c3) > 1 + kClamp && wrist_singular) {
        // At the wrist singularity θ6 turns joint 4's axis z4 freely in the arm plane, moving
        // the elbow target p13 = p5 − d5·z4 on a circle. Take the θ6 that brings p13 nearest
        // the reachable annulus: z4 towards the shoulder if too far, away if too near.
        const Eigen::Isometry3d t0 = t14_of(0.0), t90 = t14_of(kPi / 2);
        const Eigen::Vector2d u0 = t0.linear().col(2).head<2>(), u90 = t90.linear().col(2).head<2>();
        const Eigen::Vector2d p5p = (t0 * Eigen::Vector3d(0, -d4, 0)).head<2>() + dh.d[4] * u0;
        if (p5p.norm() > 0) {
          const Eigen::Vector2d u = (c3 > 0) == (a2 * a3 > 0) ? Eigen::Vector2d(p5p.normalized())
                                                               : Eigen::Vector2d(-p5p.normalized());
          t6 = std::atan2(u.dot(u90), u.dot(u0));
          t14 = t14_of(t6);
          p13 = t14 * Eigen::Vector3d(0, -d4, 0);
          c3 = c3_of(p13);
        }
      }
      if (std::abs(c3) > 1 + kClamp) continue;
      const double t3a = std::acos(clamp_unit(c3));
      for (double t3 : {t3a, -t3a}) {
        const double s3 = std::sin(t3), c3c = std::cos(t3);
        const double t2 = std::atan2(p13.y(), p13.x()) - std::atan2(a3 * s3, a2 + a3 * c3c);
        const Eigen::Isometry3d t34 = dh_transform(2, t3).inverse(Eigen::Isometry) *
                                      dh_transform(1, t2).inverse(Eigen::Isometry) * t14;
        const double t4 = std::atan2(t34.linear()(1, 0), t34.linear()(0, 0));
        Joints q{t1, t2, t3, t4, t5, t6};
        if (!config_.limits.wrap(q, ref)) continue;
        // Verify by FK (guards the clamped, near-singular cases) and drop duplicates.
        Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
        for (int i = 0; i < kDof; ++i) f = f * dh_transform(i, q[static_cast<std::size_t>(i)]);
        if (position_error(f, t06) > kVerifyPos || rotation_error(f, t06) > kVerifyRot) continue;
        bool dup = false;
        for (int k = 0; k < out.count && !dup; ++k)
          dup = max_angle_difference(out.q[static_cast<std::size_t>(k)], q) < kDuplicate;
        if (!dup && out.count < 8) out.q[static_cast<std::size_t>(out.count++)] = q;
      }
    }
  }
}

std::optional<Joints> Ur5Kinematics::ik_nearest(const Eigen::Isometry3d& tool_world, const Joints& near,
                                                const Joints& weights) const {
  IkSolutions sols;
  ik_tool(tool_world, sols, &near);
  std::optional<Joints> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (const Joints& q : sols) {
    const double d = weighted_distance(q, near, weights);
    if (d < best_d) {
      best_d = d;
      best = q;
    }
  }
  return best;
}

}  // namespace rtamp::robot
