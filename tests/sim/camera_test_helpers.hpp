// What the camera tests do to a simulation: step it while a camera pipeline takes frames
// at 10 Hz of simulated time, read the truth, and put the tool somewhere over the table
// (gripper pointing down, the first collision-free IK solution), or narrow the fixed camera.
#pragma once

#include <cmath>

#include "rtamp/robot/skills.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/sim/camera_perception.hpp"
#include "rtamp/sim/perception.hpp"
#include "rtamp/world/camera.hpp"

namespace rtamp::sim::testing {

// `frames` frames at 10 Hz of simulated time, every perceiving camera each.
inline void watch(Simulation& sim, CameraPerception& eyes, int frames) {
  const int steps = static_cast<int>(std::lround(0.1 / sim.timestep()));
  for (int k = 0; k < frames; ++k) {
    sim.step(steps);
    eyes.frame();
  }
}

inline world::Placement truth(Simulation& sim) { return Perception(sim).observe().placement(); }

// The tool at `tool`, gripper pointing down; false if no such configuration is free.
inline bool pose_tool(Simulation& sim, const Eigen::Vector3d& tool) {
  robot::Ur5Kinematics::Config cfg;
  cfg.base = robot::Ur5Kinematics::base_pose(sim.scenario().robot);
  cfg.tool_offset = sim.options().mjcf.arm.tool_offset;
  const robot::Ur5Kinematics arm(cfg);
  robot::IkSolutions q;
  const robot::Joints now = sim.arm_q();
  arm.ik_tool(robot::top_down_pose(tool, 0), q, &now);
  for (const robot::Joints& c : q)
    if (!sim.config_collides(c)) {
      sim.set_arm_configuration(c);
      return true;
    }
  return false;
}

// The tool `above` m over the top of thing i.
inline bool hover(Simulation& sim, int i, double above) {
  const Thing& t = sim.thing(i);
  Eigen::Vector3d top = sim.position(i);
  top.z() += (t.container ? t.size[2] : t.size[2] / 2) + above;
  return pose_tool(sim, top);
}

// The scene's default cameras, the fixed one narrowed to one region alone (by default the
// last: the generated scenes put their blocks in the first).
inline world::Scenario narrow_overhead(world::Scenario s, std::size_t region = SIZE_MAX) {
  std::vector<world::Camera> cams = world::default_cameras(s);
  world::Camera& o = cams.at(0);
  const world::Region& r = s.regions.at(std::min(region, s.regions.size() - 1));
  o.look_at = {r.center[0], r.center[1], r.center[2]};
  o.position = {r.center[0] - 0.05, r.center[1], r.center[2] + 0.9};
  o.fovy = 2 * std::atan(0.5 * std::max(r.size[0], r.size[1]) / 0.9 * 0.75) * 180 / M_PI;  // the region, barely
  s.cameras = cams;
  return s;
}

}  // namespace rtamp::sim::testing
