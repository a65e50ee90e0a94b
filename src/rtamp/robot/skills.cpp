#include "rtamp/robot/skills.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtamp::robot {

Grasp Grasp::block(const world::Vec3& size) {
  Grasp g;
  g.offset = Eigen::Vector3d(0, 0, size[2] / 2);
  g.yaw = 0;
  g.yaw_symmetry = std::abs(size[0] - size[1]) < 1e-9 ? 4 : 2;
  return g;
}

Grasp Grasp::tray(const world::Vec3& size, double rim, double depth) {
  Grasp g;
  g.offset = Eigen::Vector3d(size[0] / 2 - rim / 2, 0, std::max(0.0, size[2] - depth));
  g.yaw = std::numbers::pi / 2;  // tool y (finger closing) along the tray's x: across the rim
  g.yaw_symmetry = 2;
  return g;
}

Eigen::Isometry3d top_down_pose(const Eigen::Vector3d& point, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  // Rz(yaw)·Rx(π): tool x = (cos yaw, sin yaw, 0), tool z = (0, 0, −1).
  t.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  t.translation() = point;
  return t;
}

namespace {

enum class Mode { Pick, Place };

SkillPlan plan_top_down(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& thing, const Grasp& grasp,
                        const SkillOptions& o, CollisionChecker* checker, Mode mode) {
  SkillPlan plan;
  const int sym = std::max(1, grasp.yaw_symmetry);
  const double step = kTwoPi / sym;
  struct Candidate {
    double distance;
    int k;
    Joints q_pre;
  };
  std::vector<Candidate> candidates;
  auto thing_yaw = [&](int k) { return thing.yaw + (mode == Mode::Place ? k * step : 0.0); };
  auto rel_yaw = [&](int k) { return grasp.yaw + (mode == Mode::Pick ? k * step : 0.0); };
  auto grasp_point = [&](int k) -> Eigen::Vector3d {
    return thing.position + Eigen::AngleAxisd(thing_yaw(k), Eigen::Vector3d::UnitZ()) * grasp.offset;
  };
  for (int k = 0; k < sym; ++k) {
    const Eigen::Isometry3d pre =
        top_down_pose(grasp_point(k) + Eigen::Vector3d(0, 0, o.approach_height), thing_yaw(k) + rel_yaw(k));
    IkSolutions sols;
    arm.ik_tool(pre, sols, &q0);
    for (const Joints& s : sols) candidates.push_back({weighted_distance(s, q0, o.weights), k, s});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  if (candidates.empty()) {
    plan.why = "pre-grasp pose unreachable";
    return plan;
  }
  std::string last = "pre-grasp pose unreachable";
  // An arm that starts in contact (after a missed grasp, or an operator who put
  // something against the fingers) first backs straight up, unchecked, so that
  // the transit can start from a free configuration.
  std::vector<Joints> escape;
  Joints q_start = q0;
  if (checker && checker->config_collides(q0)) {
    Eigen::Isometry3d up = arm.tool_pose(q0);
    up.translation().z() += o.approach_height;
    if (auto line = cartesian_line(arm, q0, up, o.cartesian)) {
      escape = std::move(*line);
      q_start = escape.back();
    }
  }
  for (const Candidate& c : candidates) {
    if (checker && checker->config_collides(c.q_pre)) {
      last = "pre-grasp configuration collides";
      continue;
    }
    const double tool_yaw = thing_yaw(c.k) + rel_yaw(c.k);
    std::string why;
    const auto approach = cartesian_line(arm, c.q_pre, top_down_pose(grasp_point(c.k), tool_yaw), o.cartesian, &why);
    if (!approach) {
      last = "approach " + why;
      continue;
    }
    const JointPathResult transit = plan_joint_path(q_start, c.q_pre, checker, o.planner);
    if (!transit.ok) {
      last = "transit: " + transit.why;
      continue;
    }
    Trajectory tr(q0);
    if (!escape.empty()) tr.append_polyline(escape, o.limits);
    tr.append_joint_path(transit.path, o.limits);
    plan.t_transit = tr.duration();
    tr.append_polyline(*approach, o.limits);
    plan.t_approach = tr.duration();
    plan.events.push_back({mode == Mode::Pick ? GripperEvent::Kind::Close : GripperEvent::Kind::Open, tr.duration()});
    tr.append_dwell(o.gripper_seconds);
    plan.t_gripper = tr.duration();
    std::vector<Joints> retreat(approach->rbegin(), approach->rend());
    tr.append_polyline(retreat, o.limits);
    plan.cost = tool_path_length(arm, tr, o.cost_joint_step);
    plan.end = tr.end();
    plan.trajectory = std::move(tr);
    plan.tool_yaw = tool_yaw;
    plan.grasp_yaw = rel_yaw(c.k);
    plan.planned_around = transit.planned;
    plan.ok = true;
    return plan;
  }
  plan.why = "no feasible " + std::string(mode == Mode::Pick ? "grasp" : "placement") + ": " + last;
  return plan;
}

}  // namespace

SkillPlan plan_pick(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& thing, const Grasp& grasp,
                    const SkillOptions& options, CollisionChecker* checker) {
  return plan_top_down(arm, q0, thing, grasp, options, checker, Mode::Pick);
}

SkillPlan plan_place(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& target, const Grasp& grasp,
                     const SkillOptions& options, CollisionChecker* checker) {
  return plan_top_down(arm, q0, target, grasp, options, checker, Mode::Place);
}

SkillPlan plan_pick_and_place(const Ur5Kinematics& arm, const Joints& q0, const ThingPose& thing,
                              const ThingPose& target, const Grasp& grasp, const SkillOptions& options,
                              CollisionChecker* pick_checker, CollisionChecker* place_checker) {
  SkillPlan pick = plan_pick(arm, q0, thing, grasp, options, pick_checker);
  if (!pick.ok) {
    pick.why = "pick: " + pick.why;
    return pick;
  }
  Grasp held = grasp;
  held.yaw = pick.grasp_yaw;
  SkillPlan place = plan_place(arm, pick.end, target, held, options, place_checker);
  if (!place.ok) {
    place.why = "place: " + place.why;
    return place;
  }
  SkillPlan both = pick;
  const double offset = both.trajectory.duration();
  both.trajectory.append(place.trajectory);
  for (GripperEvent e : place.events) {
    e.time += offset;
    both.events.push_back(e);
  }
  both.cost = pick.cost + place.cost;
  both.end = place.end;
  both.planned_around = pick.planned_around || place.planned_around;
  return both;
}

}  // namespace rtamp::robot
