#include "rtamp/sim/camera_overlay.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/sim/camera_perception.hpp"

namespace rtamp::sim {

namespace {

// How far a detection's base may lie from the believed thing it is taken for (m, in the
// table's plane): the belief's own gate for a thing it has seen, doubled for the poses
// of partly seen things (the belief keeps their last complete pose).
double reach(const world::Belief& belief) { return 2 * belief.options().match_radius; }

std::array<std::uint8_t, 3> state_colour(const std::string& state) {
  if (state == "visible") return {46, 204, 64};
  if (state == "occluded") return {255, 133, 27};
  if (state == "held") return {0, 116, 217};
  if (state == "missing") return {255, 65, 54};
  if (state == "out-of-view") return {170, 170, 170};
  return {255, 220, 0};  // new
}

}  // namespace

std::vector<OverlayBox> overlay_boxes(const CameraImage& image, const std::vector<world::Detection>& detections,
                                      const world::Belief& belief) {
  std::vector<OverlayBox> out;
  const double max_distance = reach(belief);
  for (const world::Detection& d : detections) {
    OverlayBox box;
    box.cls = d.cls;
    world::Vec3 size = world::Object{}.size;
    bool sized = false;
    double best = INFINITY;
    for (const world::BelievedThing& t : belief.things()) {
      if (t.cls != d.cls) continue;
      if (!sized) size = t.size, sized = true;
      const double dist = std::hypot(t.base[0] - d.base[0], t.base[1] - d.base[1]);
      if (dist <= max_distance && dist < best) {
        best = dist;
        box.name = t.name;
        box.state = world::to_string(t.state);
        size = t.size;
      }
    }
    if (box.name.empty()) box.state = "new";
    box.label = (box.name.empty() ? box.cls : box.name) + " " + box.state;
    box.rgb = state_colour(box.state);
    // The fitted box's corners in the image.
    const double c = std::cos(d.yaw), s = std::sin(d.yaw);
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    bool behind = false;
    for (const double u : {-0.5, 0.5})
      for (const double v : {-0.5, 0.5})
        for (const double h : {0.0, 1.0}) {
          const Eigen::Vector3d w(d.base[0] + c * u * size[0] - s * v * size[1],
                                  d.base[1] + s * u * size[0] + c * v * size[1], d.base[2] + h * size[2]);
          const Eigen::Vector3d p = image.extrinsics.to_camera(w);
          if (p.z() <= 1e-6) {
            behind = true;
            continue;
          }
          const Eigen::Vector2d px = image.intrinsics.project(p);
          // Pixel centres are at integers: a pixel covers [u - 0.5, u + 0.5].
          x0 = std::min(x0, px.x() - 0.5), x1 = std::max(x1, px.x() + 0.5);
          y0 = std::min(y0, px.y() - 0.5), y1 = std::max(y1, px.y() + 0.5);
        }
    if (behind) continue;
    box.x0 = std::clamp(x0, 0.0, static_cast<double>(image.width));
    box.x1 = std::clamp(x1, 0.0, static_cast<double>(image.width));
    box.y0 = std::clamp(y0, 0.0, static_cast<double>(image.height));
    box.y1 = std::clamp(y1, 0.0, static_cast<double>(image.height));
    if (!(box.x1 > box.x0 && box.y1 > box.y0)) continue;
    out.push_back(std::move(box));
  }
  return out;
}

std::vector<OverlayBox> overlay_boxes(const CameraPerception& frame) {
  return overlay_boxes(frame.image(), frame.detections(), frame.belief());
}

}  // namespace rtamp::sim
