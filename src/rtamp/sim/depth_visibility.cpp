#include "rtamp/sim/depth_visibility.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtamp::sim {

world::Sight DepthVisibility::sight(const world::BelievedThing& t) const {
  if (!image_ || image_->depth.empty()) return world::Sight::OutOfView;
  const CameraImage& im = *image_;
  // The top's centre and four points towards its corners (a container: on its rims).
  const double c = std::cos(t.yaw), s = std::sin(t.yaw);
  const double fx = t.container ? 0.5 - 0.01 / t.size[0] : 0.25, fy = t.container ? 0.5 - 0.01 / t.size[1] : 0.25;
  std::array<std::array<double, 2>, 5> offsets{{{0, 0}, {fx, fy}, {-fx, fy}, {fx, -fy}, {-fx, -fy}}};
  int inside = 0, read = 0, covered = 0;
  for (std::size_t k = t.container ? 1 : 0; k < offsets.size(); ++k) {
    const double u = offsets[k][0] * t.size[0], v = offsets[k][1] * t.size[1];
    const Eigen::Vector3d w(t.base[0] + c * u - s * v, t.base[1] + s * u + c * v, t.base[2] + t.size[2]);
    const Eigen::Vector3d p = im.extrinsics.to_camera(w);
    if (p.z() <= 0) continue;
    const Eigen::Vector2d px = im.intrinsics.project(p);
    const long col = std::lround(px.x()), row = std::lround(px.y());
    if (col < 0 || row < 0 || col >= im.width || row >= im.height) continue;
    ++inside;
    const float z = im.depth[static_cast<std::size_t>(row) * static_cast<std::size_t>(im.width) + static_cast<std::size_t>(col)];
    if (z <= 0) continue;
    ++read;
    const double sigma = noise_.a + noise_.b * p.z() * p.z();
    if (z < p.z() - std::max(min_margin_, 3 * sigma)) ++covered;
  }
  if (inside == 0) return world::Sight::OutOfView;
  if (read == 0 || 2 * covered >= read) return world::Sight::Occluded;
  return world::Sight::Visible;
}

}  // namespace rtamp::sim
