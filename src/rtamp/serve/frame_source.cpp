#include "rtamp/serve/frame_source.hpp"

namespace rtamp::serve {

Frame SimFrames::frame() {
  const sim::Simulation& sim = world_.session().sim();
  Frame f;
  f.t = sim.time();
  const robot::Joints q = sim.arm_q();
  f.q = std::array<double, 6>{q[0], q[1], q[2], q[3], q[4], q[5]};
  const Eigen::Vector3d tool = sim.tool_pose().translation();
  f.tool = {tool.x(), tool.y(), tool.z()};
  if (sim.held() >= 0) f.held = sim.thing(sim.held()).name;
  for (int i = 0; i < static_cast<int>(sim.things().size()); ++i) {
    const sim::Thing& t = sim.thing(i);
    if (!t.present || t.name.empty()) continue;
    Frame::Thing ft;
    ft.name = t.name;
    ft.cls = t.cls;
    ft.container = t.container;
    ft.size = t.size;
    const Eigen::Isometry3d pose = sim.pose(i);
    // Blocks' bodies are centred; trays' bodies start at their base.
    const Eigen::Vector3d base =
        t.container ? pose.translation() : Eigen::Vector3d(pose * Eigen::Vector3d(0, 0, -t.size[2] / 2));
    ft.pos = {base.x(), base.y(), base.z()};
    const Eigen::Quaterniond r(pose.rotation());
    ft.quat = {r.w(), r.x(), r.y(), r.z()};
    const std::string* at = seen_.location_of(t.name);
    ft.at = i == sim.held() ? "hand" : at ? *at : "none";
    f.things.push_back(std::move(ft));
  }
  return f;
}

Frame SymbolicFrames::frame() { return layout_.frame(world_.time(), world_.truth(), world_.hand_point()); }

}  // namespace rtamp::serve
