// Whether a camera frame would show a thing where the belief holds it (world/belief.hpp's
// Visibility), read from the depth image alone: a few points of the thing's top (a block's
// top face, a container's rims) are projected into the image and compared with the depth
// read there. Nearer by more than the margin: something covers the spot (the arm, a hand);
// within it or farther: the spot is in plain view, so the thing would be seen if it were
// there.
//
// Verdict: no point inside the image: OutOfView; at least half of the points with a
// reading covered, or no reading at all: Occluded; otherwise Visible. The margin grows
// with the camera's depth noise at the point (3 sigma, at least min_margin).
#pragma once

#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/world/belief.hpp"

namespace rtamp::sim {

class DepthVisibility : public world::Visibility {
 public:
  explicit DepthVisibility(world::DepthNoise noise, double min_margin = 0.01) : noise_(noise), min_margin_(min_margin) {}
  // The frame the next sight() calls read (kept by reference: it must outlive them).
  void set_frame(const CameraImage& image) { image_ = &image; }
  world::Sight sight(const world::BelievedThing& thing) const override;

 private:
  world::DepthNoise noise_;
  double min_margin_;
  const CameraImage* image_ = nullptr;
};

}  // namespace rtamp::sim
