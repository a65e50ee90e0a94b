#include "rtamp/robot/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rtamp::robot {

TrapezoidProfile TrapezoidProfile::make(double distance, double vmax, double amax) {
  TrapezoidProfile p;
  if (!(distance > 0) || !(vmax > 0) || !(amax > 0)) return p;
  p.distance = distance;
  p.accel = amax;
  if (vmax * vmax / amax >= distance) {  // triangular: never reaches vmax
    p.t_acc = std::sqrt(distance / amax);
    p.vpeak = amax * p.t_acc;
    p.t_cruise = 0;
  } else {
    p.t_acc = vmax / amax;
    p.vpeak = vmax;
    p.t_cruise = (distance - vmax * vmax / amax) / vmax;
  }
  return p;
}

void TrapezoidProfile::eval(double t, double& s, double& sd) const {
  const double T = duration();
  if (!(t > 0)) {
    s = 0;
    sd = 0;
  } else if (t < t_acc) {
    s = 0.5 * accel * t * t;
    sd = accel * t;
  } else if (t < t_acc + t_cruise) {
    s = 0.5 * accel * t_acc * t_acc + vpeak * (t - t_acc);
    sd = vpeak;
  } else if (t < T) {
    const double r = T - t;
    s = distance - 0.5 * accel * r * r;
    sd = accel * r;
  } else {
    s = distance;
    sd = 0;
  }
}

void Trajectory::check_start(const Joints& first) const {
  if (!waypoints_.empty() && max_joint_delta(first, waypoints_.back()) > 1e-9)
    throw std::invalid_argument("Trajectory: appended motion does not start where the trajectory ends");
}

double Trajectory::append_joint_path(const std::vector<Joints>& path, const MotionLimits& limits) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) append_polyline({path[i], path[i + 1]}, limits);
  if (waypoints_.empty() && !path.empty()) waypoints_.push_back(path.front());
  return duration_;
}

double Trajectory::append_polyline(const std::vector<Joints>& path, const MotionLimits& limits) {
  if (path.empty()) return duration_;
  check_start(path.front());
  if (waypoints_.empty()) waypoints_.push_back(path.front());
  const std::size_t first = waypoints_.size() - 1;
  double vu = std::numeric_limits<double>::infinity(), au = vu;
  for (std::size_t i = 1; i < path.size(); ++i) {
    if (max_joint_delta(path[i], waypoints_.back()) < 1e-12) continue;  // drop repeated points
    const Joints& a = waypoints_.back();
    for (int j = 0; j < kDof; ++j) {
      const auto k = static_cast<std::size_t>(j);
      const double d = std::abs(path[i][k] - a[k]);
      if (d > 0) {
        vu = std::min(vu, limits.vmax[k] / d);
        au = std::min(au, limits.amax[k] / d);
      }
    }
    waypoints_.push_back(path[i]);
  }
  const std::size_t count = waypoints_.size() - first;
  if (count < 2) return duration_;
  Piece p;
  p.t0 = duration_;
  p.first = first;
  p.count = count;
  p.profile = TrapezoidProfile::make(static_cast<double>(count - 1), vu, au);
  pieces_.push_back(p);
  duration_ += p.duration();
  return duration_;
}

double Trajectory::append_dwell(double seconds) {
  if (!(seconds > 0) || waypoints_.empty()) return duration_;
  Piece p;
  p.t0 = duration_;
  p.first = waypoints_.size() - 1;
  p.count = 1;
  p.dwell = seconds;
  pieces_.push_back(p);
  duration_ += seconds;
  return duration_;
}

double Trajectory::append(const Trajectory& other) {
  if (other.empty()) return duration_;
  check_start(other.start());
  if (waypoints_.empty()) {
    *this = other;
    return duration_;
  }
  const std::size_t offset = waypoints_.size() - 1;  // other's waypoint 0 is our last
  waypoints_.insert(waypoints_.end(), other.waypoints_.begin() + 1, other.waypoints_.end());
  for (Piece p : other.pieces_) {
    p.t0 += duration_;
    p.first += offset;
    pieces_.push_back(p);
  }
  duration_ += other.duration_;
  return duration_;
}

Trajectory::Sample Trajectory::sample(double t) const {
  Sample s;
  if (waypoints_.empty()) return s;
  if (pieces_.empty() || !(t > 0)) {
    s.q = waypoints_.front();
    return s;
  }
  if (t >= duration_) {
    s.q = waypoints_.back();
    return s;
  }
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double x, const Piece& p) { return x < p.t0; });
  const Piece& p = *(it - 1);
  if (p.dwell > 0) {
    s.q = waypoints_[p.first];
    return s;
  }
  double u = 0, ud = 0;
  p.profile.eval(t - p.t0, u, ud);
  const std::size_t n = p.count - 1;
  std::size_t i = static_cast<std::size_t>(std::floor(u));
  if (i >= n) i = n - 1;
  const double f = u - static_cast<double>(i);
  const Joints& a = waypoints_[p.first + i];
  const Joints& b = waypoints_[p.first + i + 1];
  for (std::size_t j = 0; j < kDof; ++j) {
    s.q[j] = a[j] + f * (b[j] - a[j]);
    s.qd[j] = ud * (b[j] - a[j]);
  }
  return s;
}

std::optional<std::vector<Joints>> cartesian_line(const Ur5Kinematics& arm, const Joints& q_start,
                                                  const Eigen::Isometry3d& goal, const CartesianOptions& options,
                                                  std::string* why) {
  const Eigen::Isometry3d start = arm.tool_pose(q_start);
  const Eigen::Vector3d p0 = start.translation(), p1 = goal.translation();
  const Eigen::Quaterniond r0(start.linear()), r1(goal.linear());
  const double dist = (p1 - p0).norm();
  const double angle = r0.angularDistance(r1);
  const int n = std::max({1, static_cast<int>(std::ceil(dist / options.step)),
                          static_cast<int>(std::ceil(angle / options.angle_step))});
  std::vector<Joints> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  out.push_back(q_start);
  for (int i = 1; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    if (i == n) {
      pose = goal;
    } else {
      pose.linear() = r0.slerp(s, r1).toRotationMatrix();
      pose.translation() = p0 + s * (p1 - p0);
    }
    const auto q = arm.ik_nearest(pose, out.back(), options.weights);
    if (!q) {
      if (why) *why = "straight line: sample " + std::to_string(i) + "/" + std::to_string(n) + " is unreachable";
      return std::nullopt;
    }
    if (max_joint_delta(*q, out.back()) > options.max_joint_jump) {
      if (why) *why = "straight line: joint jump at sample " + std::to_string(i) + "/" + std::to_string(n);
      return std::nullopt;
    }
    out.push_back(*q);
  }
  return out;
}

namespace {
double interval_length(const Ur5Kinematics& arm, const Joints& a, const Joints& b, double max_joint_step,
                       Eigen::Vector3d& prev) {
  const double d = max_joint_delta(a, b);
  if (d == 0) return 0;
  const int m = std::max(1, static_cast<int>(std::ceil(d / max_joint_step)));
  double len = 0;
  for (int k = 1; k <= m; ++k) {
    Joints q;
    const double f = static_cast<double>(k) / m;
    for (std::size_t j = 0; j < kDof; ++j) q[j] = a[j] + f * (b[j] - a[j]);
    const Eigen::Vector3d p = arm.tool_point(q);
    len += (p - prev).norm();
    prev = p;
  }
  return len;
}
}  // namespace

double tool_path_length(const Ur5Kinematics& arm, const std::vector<Joints>& path, double max_joint_step) {
  if (path.size() < 2) return 0;
  Eigen::Vector3d prev = arm.tool_point(path.front());
  double len = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) len += interval_length(arm, path[i], path[i + 1], max_joint_step, prev);
  return len;
}

double tool_path_length(const Ur5Kinematics& arm, const Trajectory& trajectory, double max_joint_step) {
  const auto& w = trajectory.waypoints();
  if (w.size() < 2) return 0;
  Eigen::Vector3d prev = arm.tool_point(w.front());
  double len = 0;
  for (const auto& p : trajectory.pieces()) {
    if (p.dwell > 0) continue;
    prev = arm.tool_point(w[p.first]);
    for (std::size_t i = p.first; i + 1 < p.first + p.count; ++i) len += interval_length(arm, w[i], w[i + 1], max_joint_step, prev);
  }
  return len;
}

}  // namespace rtamp::robot
