// Perception through cameras, as the paper's robot had it (Section V): each frame one of
// the perceiving cameras (by default the scenario's primary one; any of its cameras, the
// wrist one too) is rendered headless, its things detected from pixels
// (camera_detector.hpp), the frame's depth tells where the camera could see
// (depth_visibility.hpp), and both are folded into one belief (world/belief.hpp) together
// with what the robot knows of its own gripper (that it grasped something, where its tool
// is): the thing grasped is the believed thing of its class nearest the tool.
//
// Several cameras: each frame updates the belief with that camera's detections and
// visibility. A believed thing outside the frame's image is OutOfView only when it lies
// outside every perceiving camera's last frame too; outside this one but inside another's
// it is Elsewhere (world::Sight): this frame leaves it as the camera that sees it left it,
// so a moving camera looking away never makes a thing Missing or resets its clock.
//
// Invariants: reads the simulation only through the rendered RGB and depth images and
// the arm's own state, never the things' poses; a camera's extrinsics are read from the
// simulation at its frame (the wrist camera follows the flange); the same seed gives the
// same frames.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rtamp/sim/camera_detector.hpp"
#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/depth_visibility.hpp"
#include "rtamp/sim/helper_thread.hpp"
#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/belief.hpp"

namespace rtamp::sim {

struct CameraPerceptionOptions {
  // Which of world::cameras_of(scenario) perceive, each at its own rate; empty: the
  // primary one (world::primary_camera).
  std::vector<std::string> cameras;
  world::BeliefOptions belief;
  std::uint64_t seed = 1;  // of the depth noise
};

class CameraPerception {
 public:
  // Throws rtamp::Error on an unknown or repeated camera or when offscreen rendering is
  // unavailable.
  CameraPerception(const Simulation& sim, CameraPerceptionOptions options = {});
  ~CameraPerception();
  // One frame of perceiving camera `k` (0 <= k < cameras().size()) at the simulation's
  // current time.
  void frame(std::size_t k);
  // One frame of each perceiving camera in turn.
  void frame();
  const world::Belief& belief() const { return belief_; }
  // The perceiving cameras, in the order asked.
  const std::vector<world::Camera>& cameras() const { return perceiving_; }
  // The last frame's (any camera's): its image, detections and camera.
  const CameraImage& image() const;
  const std::vector<world::Detection>& detections() const { return detections_; }
  const std::string& camera_name() const { return perceiving_[last_].name; }
  // Frames taken so far, of every camera (each one render: RGB and depth, never the
  // segmentation pass).
  std::size_t frames() const { return frames_; }

 private:
  struct Eye;
  class Views;
  const Simulation& sim_;
  CameraRig rig_;
  std::vector<world::Camera> perceiving_;
  std::vector<std::unique_ptr<Eye>> eyes_;
  world::Belief belief_;
  std::vector<world::Detection> detections_;
  std::size_t frames_ = 0, last_ = 0;
  int held_ = -1;          // the simulation's thing in the gripper at the last frame
  std::string held_name_;  // its name in the belief
  HelperThread helper_;    // a frame's depth noise while its colours are segmented
};

}  // namespace rtamp::sim
