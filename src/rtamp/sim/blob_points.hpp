// The top faces seen in a colour blob, as 3-D points (world frame) on each face's plane.
// Things rest upright, so a thing's top face is horizontal: the blob's top height is the
// median height of its points near the highest (within top_band plus 3 sigma of the
// depth noise below the 90th percentile); the pixels within top_band plus 2.5 sigma of it
// are the top face. With `split` (things of one colour that show as one blob: the nearer
// one's side face covers the gap between them, but their top faces do not touch in the
// image) the top-face pixels are joined with their 8-neighbours into one cluster per face;
// without it (a container: the things on it cut its image apart) they form one cluster.
// Each cluster's pixels are then re-projected: the pixel's ray meets the plane of the
// cluster's own median height (or the known top), so the depth noise moves the height,
// never the outline.
// Pixels without a depth reading are left out; clusters under min_points are dropped.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "rtamp/sim/colour_segmentation.hpp"
#include "rtamp/sim/pinhole.hpp"
#include "rtamp/world/camera.hpp"

namespace rtamp::sim {

struct BlobPointsOptions {
  bool split = true;
  double top_band = 0.003;  // m, on top of the depth noise's allowance
  int min_points = 12;
  int smooth_radius = 1;    // each depth becomes the median of the blob's readings within this many pixels
  world::DepthNoise noise;  // the camera's, for the allowance (a + b z² at the blob's depth)
  // The top height when it is known (a tray on the table: the table's height plus the
  // tray's); the top face's pixels are then those near it, and all are re-projected onto it.
  std::optional<double> top;
};

std::vector<std::vector<Eigen::Vector3d>> blob_points(const ColourBlob& blob, const std::vector<float>& depth, int width,
                                                      const Intrinsics& K, const Extrinsics& E,
                                                      const BlobPointsOptions& options = {});

// Clusters (of several blobs of one colour) joined when points of theirs lie within
// max_gap of each other in the table's plane: a container whose image the things on it
// cut into parts is one cluster again (two containers nearer than max_gap become one).
std::vector<std::vector<Eigen::Vector3d>> join_near(std::vector<std::vector<Eigen::Vector3d>> clusters, double max_gap);

}  // namespace rtamp::sim
