#include "rtamp/sim/camera_perception.hpp"

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
  detector_.detect(image_, detections_);
  visibility_.set_frame(image_);
  world::Gripper gripper;
  if (sim_.held() >= 0) gripper.holds = sim_.thing(sim_.held()).name;
  const Eigen::Vector3d tool = sim_.tool_pose().translation();
  gripper.tool = {tool.x(), tool.y(), tool.z()};
  belief_.update(sim_.time(), detections_, visibility_, gripper);
}

}  // namespace rtamp::sim
