// Perception through a camera, as the paper's robot had it (Section V): each frame one of
// the scenario's cameras is rendered headless, its things detected from pixels
// (camera_detector.hpp), the frame's depth tells where the camera could see
// (depth_visibility.hpp), and both are folded into the belief (world/belief.hpp) together
// with what the robot knows of its own gripper (that it grasped something, where its tool
// is): the thing grasped is the believed thing of its class nearest the tool.
//
// Invariants: reads the simulation only through the rendered RGB and depth images and
// the arm's own state, never the things' poses; the same seed gives the same frames.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/sim/camera_detector.hpp"
#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/depth_visibility.hpp"
#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/belief.hpp"

namespace rtamp::sim {

struct CameraPerceptionOptions {
  std::string camera = "overhead";  // one of world::cameras_of(scenario)
  world::BeliefOptions belief;
  std::uint64_t seed = 1;  // of the depth noise
};

class CameraPerception {
 public:
  // Throws rtamp::Error on an unknown camera or when offscreen rendering is unavailable.
  CameraPerception(const Simulation& sim, CameraPerceptionOptions options = {});
  // One frame at the simulation's current time.
  void frame();
  const world::Belief& belief() const { return belief_; }
  const CameraImage& image() const { return image_; }
  const std::vector<world::Detection>& detections() const { return detections_; }
  const std::string& camera_name() const { return rig_.cameras()[camera_].name; }
  // Frames taken so far (each one render: RGB and depth, never the segmentation pass).
  std::size_t frames() const { return frames_; }

 private:
  const Simulation& sim_;
  CameraRig rig_;
  std::size_t camera_;
  CameraDetector detector_;
  DepthVisibility visibility_;
  world::Belief belief_;
  CameraImage image_;
  std::vector<world::Detection> detections_;
  std::size_t frames_ = 0;
  int held_ = -1;          // the simulation's thing in the gripper at the last frame
  std::string held_name_;  // its name in the belief
};

}  // namespace rtamp::sim
