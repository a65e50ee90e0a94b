#include "rtamp/sim/skill_runner.hpp"

#include <algorithm>
#include <cmath>

namespace rtamp::sim {

SkillRunner::SkillRunner(Simulation& sim, Controller& controller, SkillRunnerOptions options)
    : sim_(sim), controller_(controller), options_(std::move(options)) {
  robot::Ur5Kinematics::Config cfg;
  cfg.base = robot::Ur5Kinematics::base_pose(sim.scenario().robot);
  cfg.tool_offset = sim.options().mjcf.arm.tool_offset;
  arm_ = robot::Ur5Kinematics(cfg);
}

robot::Grasp SkillRunner::grasp_for(int i) const { return grasp_for(sim_.thing(i).size, sim_.thing(i).container); }

robot::Grasp SkillRunner::grasp_for(const world::Vec3& size, bool container) {
  if (!container) return robot::Grasp::block(size);
  // A long rim (+y side; 2-fold: or the -y side), fingers closing across it (tool y
  // along the tray's y), tool point 1 cm below the rim top.
  robot::Grasp g;
  const double h = std::max(size[2], kTrayPlate + 0.005);
  g.offset = Eigen::Vector3d(0, size[1] / 2 - kTrayRim / 2, std::max(kTrayPlate + 0.006, h - 0.01));
  g.yaw = 0;
  g.yaw_symmetry = 2;
  return g;
}

robot::Grasp SkillRunner::held_grasp(int i) const {
  // The thing's base frame seen from the tool (the weld keeps it so), then the same
  // relation under a top-down tool at the origin with yaw 0: the thing's base lies at
  // p, turned by yaw, so the tool point is -p in the thing's frame and the tool's yaw
  // relative to the thing is -yaw.
  Eigen::Isometry3d thing = sim_.pose(i);
  thing.translation() = base_point(sim_, i);
  const Eigen::Isometry3d rel = sim_.tool_pose().inverse() * thing;
  const Eigen::Isometry3d seen = robot::top_down_pose(Eigen::Vector3d::Zero(), 0) * rel;
  const double yaw = std::atan2(seen.linear()(1, 0), seen.linear()(0, 0));
  robot::Grasp g = grasp_for(i);
  g.offset = Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()) * -seen.translation();
  g.yaw = -yaw;
  return g;
}

std::optional<world::Vec3> SkillRunner::place_spot(int i, const std::string& location) const {
  const Thing& t = sim_.thing(i);
  std::vector<int> exclude{i};
  exclude.insert(exclude.end(), carried_.begin(), carried_.end());
  // Keep the fingers' room by the long rims of a target tray free (they grasp there).
  std::vector<world::Footprint> keep_clear;
  const int target = sim_.find(location);
  if (target >= 0 && sim_.thing(target).container && sim_.thing(target).present) {
    const Thing& c = sim_.thing(target);
    const Eigen::Isometry3d cp = sim_.pose(target);
    for (int s : {-1, 1}) {
      const double inner = c.size[1] / 2 - kTrayRim / 2 - sim_.finger_max() - kFingerPad / 2;
      const Eigen::Vector3d z = cp * Eigen::Vector3d(0, s * inner, 0);
      keep_clear.push_back(world::footprint_at({z.x(), z.y(), 0}, {0.026, kFingerPad + 0.002, 0}));
    }
  }
  return free_spot(sim_, location, {t.size, t.container}, exclude, options_.place_gap, keep_clear);
}

bool SkillRunner::start_pick(const std::string& object, const std::optional<SeenThing>& seen) {
  const int found = sim_.find(object);
  const int i = found >= 0 && sim_.thing(found).present ? found : -1;
  if (i < 0 && !seen) {
    controller_.fail("'" + object + "' is not in the scene");
    return false;
  }
  if (sim_.held() >= 0) {
    controller_.fail("the gripper already holds '" + sim_.thing(sim_.held()).name + "'");
    return false;
  }
  carried_.clear();
  if (i >= 0 && sim_.thing(i).container) carried_ = contents_of(sim_, i);
  const robot::Grasp g = i >= 0 ? grasp_for(i) : grasp_for(seen->size, seen->container);
  SimCollisionChecker checker(sim_, carried_);
  robot::SkillPlan p = robot::plan_pick(arm_, sim_.arm_q(), seen ? seen->pose : thing_pose(sim_, i), g, options_.skill,
                                        options_.collision_checking ? &checker : nullptr);
  if (!p.ok) {
    controller_.fail("cannot pick '" + object + "': " + p.why);
    return false;
  }
  MotionPlan m;
  m.trajectory = std::move(p.trajectory);
  for (const auto& e : p.events) m.events.push_back({e.time, e.kind == robot::GripperEvent::Kind::Close});
  m.object = object;
  m.absent_ok = seen.has_value();
  m.cost = p.cost;
  m.skill = "pick";
  controller_.start(std::move(m));
  return controller_.status() == Status::Running;
}

bool SkillRunner::start_place(const std::string& location) {
  const int i = sim_.held();
  if (i < 0) {
    controller_.fail("nothing in the gripper to place");
    return false;
  }
  const std::string object = sim_.thing(i).name;
  if (location == object) {
    controller_.fail("cannot place '" + object + "' into itself");
    return false;
  }
  // The rule book first (capacity, room, fit, nesting), in the symbolic world's words.
  const Thing& t = sim_.thing(i);
  std::vector<int> riding{i};
  riding.insert(riding.end(), carried_.begin(), carried_.end());
  if (std::string why = options_.space_rules ? space_refusal(sim_, object, {t.size, t.container}, location, riding)
                                             : std::string();
      !why.empty()) {
    controller_.fail("cannot place " + object + ": " + why);
    return false;
  }
  sim_.clear_reserved_spot();  // our own earlier reservation is no obstacle
  auto spot = place_spot(i, location);
  if (!spot) {
    controller_.fail("no free spot for '" + object + "' in '" + location + "'");
    return false;
  }
  robot::ThingPose target;
  target.position = Eigen::Vector3d((*spot)[0], (*spot)[1], (*spot)[2] + options_.drop_height);
  target.yaw = thing_pose(sim_, i).yaw;
  const robot::Grasp g = held_grasp(i);
  std::vector<int> ignore = carried_;
  SimCollisionChecker checker(sim_, ignore);
  robot::SkillPlan p = robot::plan_place(arm_, sim_.arm_q(), target, g, options_.skill,
                                         options_.collision_checking ? &checker : nullptr);
  if (!p.ok) {
    controller_.fail("cannot place '" + object + "' in '" + location + "': " + p.why);
    return false;
  }
  const Thing& held = sim_.thing(i);
  sim_.reserve_spot(world::footprint_at(*spot, {held.size[0] + 2 * options_.place_gap,
                                                held.size[1] + 2 * options_.place_gap, 0}));
  MotionPlan m;
  m.trajectory = std::move(p.trajectory);
  for (const auto& e : p.events) m.events.push_back({e.time, e.kind == robot::GripperEvent::Kind::Close});
  m.object = object;
  m.cost = p.cost;
  m.skill = "place";
  // The rule book again at the moment of the release: a person may have filled the
  // location while the arm carried the thing there.
  if (options_.space_rules)
    m.release_check = [this, object, body = world::Body{t.size, t.container}, location, riding] {
      const std::string why = space_refusal(sim_, object, body, location, riding);
      return why.empty() ? why : "cannot place " + object + ": " + why;
    };
  controller_.start(std::move(m));
  return controller_.status() == Status::Running;
}

bool SkillRunner::start_retreat(double height) {
  if (sim_.held() >= 0) {
    controller_.fail("cannot back off holding '" + sim_.thing(sim_.held()).name + "'");
    return false;
  }
  const robot::Joints q0 = sim_.arm_q();
  Eigen::Isometry3d up = arm_.tool_pose(q0);
  if (up.translation().z() >= height + 0.05) return true;  // already clear of the table
  up.translation().z() += height;
  std::string why;
  const auto line = robot::cartesian_line(arm_, q0, up, options_.skill.cartesian, &why);
  if (!line) {
    controller_.fail("cannot back off: " + why);
    return false;
  }
  MotionPlan m;
  m.trajectory = robot::Trajectory(q0);
  m.trajectory.append_polyline(*line, options_.skill.limits);
  m.cost = robot::tool_path_length(arm_, m.trajectory, options_.skill.cost_joint_step);
  m.skill = "retreat";
  controller_.start(std::move(m));
  return controller_.status() == Status::Running;
}

robot::Joints SkillRunner::home() const {
  const mjModel* m = sim_.model();
  const int key = mj_name2id(m, mjOBJ_KEY, "home");
  robot::Joints q{};
  for (int j = 0; j < 6; ++j) q[j] = key >= 0 ? m->key_qpos[key * m->nq + j] : m->qpos0[j];
  return q;
}

bool SkillRunner::start_park(double height) {
  if (sim_.held() >= 0) {
    controller_.fail("cannot park holding '" + sim_.thing(sim_.held()).name + "'");
    return false;
  }
  const robot::Joints q0 = sim_.arm_q(), home_q = home();
  double far = 0;
  for (int j = 0; j < 6; ++j) far = std::max(far, std::abs(q0[j] - home_q[j]));
  if (far < 0.02) return true;  // rad: home already
  MotionPlan m;
  m.trajectory = robot::Trajectory(q0);
  robot::Joints from = q0;
  Eigen::Isometry3d up = arm_.tool_pose(q0);
  if (up.translation().z() < height) {
    up.translation().z() = height;
    std::string why;
    const auto line = robot::cartesian_line(arm_, q0, up, options_.skill.cartesian, &why);
    if (!line) {
      controller_.fail("cannot park: " + why);
      return false;
    }
    m.trajectory.append_polyline(*line, options_.skill.limits);
    from = line->back();
  }
  SimCollisionChecker checker(sim_);
  for (int k = 1; k <= 20; ++k) {
    robot::Joints q;
    for (int j = 0; j < 6; ++j) q[j] = from[j] + (home_q[j] - from[j]) * k / 20.0;
    if (checker.config_collides(q)) {
      controller_.fail("cannot park: the way home collides");
      return false;
    }
  }
  m.trajectory.append_polyline({from, home_q}, options_.skill.limits);
  m.cost = robot::tool_path_length(arm_, m.trajectory, options_.skill.cost_joint_step);
  m.skill = "park";
  controller_.start(std::move(m));
  return controller_.status() == Status::Running;
}

Status SkillRunner::run_controller(const std::function<void()>& on_step, double max_time) {
  const double until = sim_.time() + max_time;
  while (controller_.status() == Status::Running) {
    if (sim_.time() >= until) {
      controller_.halt();
      controller_.fail("timed out");
      break;
    }
    controller_.step();
    if (on_step) on_step();
  }
  return controller_.status();
}

ActionResult SkillRunner::move(const std::string& object, const std::string& location,
                               const std::function<void()>& on_step) {
  ActionResult r;
  r.action = "move " + object + " " + location;
  r.start = sim_.time();
  auto finish = [&] {
    r.status = controller_.status();
    r.reason = controller_.reason();
    r.duration = sim_.time() - r.start;
    return r;
  };
  if (start_pick(object)) {
    r.cost += controller_.plan().cost;
    run_controller(on_step);
  }
  if (controller_.status() != Status::Success) return finish();
  if (start_place(location)) {
    r.cost += controller_.plan().cost;
    run_controller(on_step);
  }
  carried_.clear();
  return finish();
}

}  // namespace rtamp::sim
