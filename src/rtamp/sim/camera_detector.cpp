#include "rtamp/sim/camera_detector.hpp"

#include <cmath>

#include "rtamp/sim/blob_points.hpp"
#include "rtamp/sim/box_fit.hpp"

namespace rtamp::sim {

CameraDetector::CameraDetector(const world::Scenario& s, world::DepthNoise noise, CameraDetectorOptions options)
    : segmenter_(scene_colours(s), options.segmentation), noise_(noise), options_(options) {
  for (const KnownColour& c : segmenter_.colours()) {
    ClassInfo info;
    if (c.thing) {
      info.known = true;
      info.container = c.label == "tray";
      info.size = info.container ? world::Container{}.size : world::Object{}.size;
      for (const auto& i : s.interventions)
        if (i.cls == c.label && i.kind == world::Change::Kind::AddContainer) info.container = true;
      bool sized = false;
      for (const auto& k : s.containers)
        if (!sized && k.cls == c.label) info.container = true, info.size = k.size, sized = true;
      for (const auto& o : s.objects)
        if (!sized && o.cls == c.label) info.container = false, info.size = o.size, sized = true;
    }
    class_of_colour_.push_back(info);
  }
}

void CameraDetector::detect(const CameraImage& image, std::vector<world::Detection>& out) {
  out.clear();
  segmenter_.segment(image.rgb.data(), image.width, image.height, segmentation_);
  const Eigen::Vector3d eye = image.extrinsics.to_world(Eigen::Vector3d::Zero());
  // Containers' parts by colour, joined before they are fitted.
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> parts(class_of_colour_.size());
  for (const ColourBlob& blob : segmentation_.blobs) {
    const ClassInfo& info = class_of_colour_[blob.colour];
    if (!info.known) continue;
    BlobPointsOptions bo;
    bo.split = !info.container;
    bo.noise = noise_;
    if (info.container) bo.top = info.size[2];  // containers stand on the table (z = 0)
    for (auto& pts : blob_points(blob, image.depth, image.width, image.intrinsics, image.extrinsics, bo)) {
      if (info.container) {
        parts[blob.colour].push_back(std::move(pts));
        continue;
      }
      const BoxFit f = fit_box(pts, info.size, false, eye);
      out.push_back({segmenter_.colours()[blob.colour].label, {f.base.x(), f.base.y(), f.base.z()}, f.yaw, f.complete});
    }
  }
  for (std::size_t c = 0; c < parts.size(); ++c) {
    if (parts[c].empty()) continue;
    for (const auto& pts : join_near(std::move(parts[c]), options_.container_gap)) {
      BoxFitOptions fo;
      // A container's points are its rims' tops, not a filled face: their spacing is a pixel's footprint.
      fo.spacing = (pts.front() - eye).norm() / image.intrinsics.fx;
      const BoxFit f = fit_box(pts, class_of_colour_[c].size, true, eye, fo);
      out.push_back({segmenter_.colours()[c].label, {f.base.x(), f.base.y(), f.base.z()}, f.yaw, f.complete});
    }
  }
}

}  // namespace rtamp::sim
