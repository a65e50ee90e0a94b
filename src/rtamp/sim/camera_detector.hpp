// Detections from one camera frame, the paper's way (Section V): the RGB image segmented
// by the scene's known colours, each blob's top faces found with the depth image, and a
// box of its class's known size fitted to each face (an object) or to a container's rims
// (its parts, cut apart by the things on it, joined again). Objects of one colour that
// touch show one top face of k footprints: it is cut into k (k-means). A detection names a class,
// never a thing: identity is the belief's (world/belief.hpp).
//
// Invariants: uses only the RGB and depth images and the camera's calibration (never the
// segmentation pass); a class's size is the first declared thing's of that class; storage
// is kept between frames.
#pragma once

#include <vector>

#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/colour_segmentation.hpp"
#include "rtamp/world/belief.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

struct CameraDetectorOptions {
  ColourSegmentationOptions segmentation;
  double container_gap = 0.05;  // m: a container's parts closer than this are one container
};

class CameraDetector {
 public:
  // `noise`: the camera's depth noise (its allowance when finding top faces). Classes the
  // segmentation cannot tell apart are the caller's to refuse first, with their location
  // (check_scene_colours; Perception does, before any rendering context exists).
  CameraDetector(const world::Scenario& s, world::DepthNoise noise, CameraDetectorOptions options = {});
  void detect(const CameraImage& image, std::vector<world::Detection>& out) {
    segment(image);
    fit(image, out);
  }
  // detect() in two steps: segment() reads the RGB image only (so another thread may
  // meanwhile finish the depth image), fit() the depth image and segment()'s blobs.
  void segment(const CameraImage& image);
  void fit(const CameraImage& image, std::vector<world::Detection>& out);
  const ColourSegmenter& segmenter() const { return segmenter_; }

 private:
  struct ClassInfo {
    bool known = false;
    bool container = false;
    world::Vec3 size{};
  };
  ColourSegmenter segmenter_;
  world::DepthNoise noise_;
  CameraDetectorOptions options_;
  std::vector<ClassInfo> class_of_colour_;  // by the segmenter's colour index
  bool split_touching(const std::vector<Eigen::Vector3d>& points, const world::Vec3& size, const Eigen::Vector3d& eye,
                      double fx, const std::string& cls, std::vector<world::Detection>& out);
  ColourSegmentation segmentation_;
  std::vector<std::vector<Eigen::Vector3d>> bands_;
};

}  // namespace rtamp::sim
