// The pose of a thing of known size from the 3-D points (world frame) of its pixels: the
// box is fitted, not the raw centroid (which the visible faces bias by about a
// centimetre). Things rest upright, so the fit is a rectangle in the table's plane: for an
// object, around the points of its top face (the band below the highest points); for a
// container, around all its points (rims and plate lie inside its footprint). OpenCV's
// minimum-area rectangle gives the yaw, the points' trimmed extents along its axes the
// sides; the centre lies half a side in from the edge away from the camera (the edge
// towards it may carry the top of the side face that faces the camera); the base lies
// one height below the top.
//
// Invariant: `complete` only when the rectangle's sides match the known footprint within
// the tolerance — the whole outline was seen, so the centre is the thing's; a partly
// hidden thing gives complete == false and a pose no one should trust.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

struct BoxFitOptions {
  double top_band = 0.005;   // m: points this close below the top height belong to the top face
  double tolerance = 0.004;  // m: how far the seen sides may differ from the footprint's
  double side_bleed = 0.008; // m: how far the top of a side face may widen the top face towards the camera
  double trim_rows = 0.3;
  // The distance between neighbouring points (a pixel's footprint on the face); 0: from the
  // points' area, right for a filled face but not for a container's rims.
  double spacing = 0;    // left out at each end of a side's extent: this share of a row of points
};

struct BoxFit {
  bool complete = false;
  Eigen::Vector3d base = Eigen::Vector3d::Zero();  // centre of the base (world)
  double yaw = 0;                                  // rad, about world z (modulo the footprint's symmetry)
  double seen_x = 0, seen_y = 0;                   // m: the fitted rectangle's sides along the thing's x and y
  int points = 0;                                  // the points the rectangle was fitted to
};

// `size` is the thing's footprint and height (world::Object/Container size); `eye` the
// camera's centre (world). Fewer than three points give complete == false.
BoxFit fit_box(const std::vector<Eigen::Vector3d>& points, const world::Vec3& size, bool container,
               const Eigen::Vector3d& eye, const BoxFitOptions& options = {});

}  // namespace rtamp::sim
