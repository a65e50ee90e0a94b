#include "rtamp/sim/camera_perception.hpp"

#include <cmath>

namespace rtamp::sim {

namespace {

world::DepthNoise noise_of(const std::vector<world::Camera>& cameras, const std::string& name) {
  for (const auto& c : cameras)
    if (c.name == name) return c.noise;
  return {};
}

}  // namespace

CameraPerception::CameraPerception(const Simulation& sim, CameraPerceptionOptions options)
    : sim_(sim),
      rig_(sim, world::cameras_of(sim.scenario()), options.seed),
      camera_(rig_.index(options.camera, {})),
      detector_(sim.scenario(), noise_of(rig_.cameras(), options.camera)),
      visibility_(noise_of(rig_.cameras(), options.camera)),
      belief_(sim.scenario(), options.belief) {}

void CameraPerception::frame() {
  rig_.render(camera_, image_, {.noise = true, .segmentation = false});
  ++frames_;
  detector_.detect(image_, detections_);
  visibility_.set_frame(image_);
  world::Gripper gripper;
  const Eigen::Vector3d tool = sim_.tool_pose().translation();
  gripper.tool = {tool.x(), tool.y(), tool.z()};
  if (sim_.held() != held_) {
    // Just grasped: the believed thing of its class nearest the tool (the one the arm went for).
    held_ = sim_.held();
    held_name_.clear();
    double best = INFINITY;
    if (held_ >= 0)
      for (const auto& t : belief_.things())
        if (t.cls == sim_.thing(held_).cls) {
          const double d = std::hypot(t.base[0] - tool.x(), t.base[1] - tool.y());
          if (d < best) best = d, held_name_ = t.name;
        }
  }
  gripper.holds = held_name_;
  belief_.update(sim_.time(), detections_, visibility_, gripper);
}

}  // namespace rtamp::sim
