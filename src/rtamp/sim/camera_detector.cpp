#include "rtamp/sim/camera_detector.hpp"

#include <cmath>

#include <opencv2/core.hpp>

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

// Things of one colour that touch show one top face of k footprints (k from its points
// against one footprint's at this distance). Its points are then cut into k clusters
// (OpenCV's k-means, a fixed seed), each fitted. Faces swollen at their edges can make
// the count one too many (two blocks 2 cm apart were counted 3.0, each seen 4.5 cm): the
// counts nearest, one fewer (if two or more) and one more are tried in turn, and the first
// whose every fit is complete is kept (else the nearest count's).
bool CameraDetector::split_touching(const std::vector<Eigen::Vector3d>& points, const world::Vec3& size,
                                    const Eigen::Vector3d& eye, double fx, const std::string& cls,
                                    std::vector<world::Detection>& out) {
  const double pixel = (points.front() - eye).norm() / fx;  // a pixel's footprint on the face
  const double per_thing = size[0] * size[1] / (pixel * pixel);
  const double count = static_cast<double>(points.size()) / per_thing;
  const int nearest = static_cast<int>(std::lround(count));
  if (nearest < 2 || nearest > 8) return false;
  cv::Mat xy(static_cast<int>(points.size()), 2, CV_32F), labels;
  for (std::size_t i = 0; i < points.size(); ++i) {
    xy.at<float>(static_cast<int>(i), 0) = static_cast<float>(points[i].x());
    xy.at<float>(static_cast<int>(i), 1) = static_cast<float>(points[i].y());
  }
  const std::size_t first = out.size();
  std::size_t first_tried = first;  // the end of the first count's fits
  for (const int k : {nearest, nearest - 1, nearest + 1}) {
    if (k < 2 || k > 8) continue;
    cv::theRNG().state = 0x5eed;
    cv::kmeans(xy, k, labels, cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 20, 1e-5), 3,
               cv::KMEANS_PP_CENTERS);
    bands_.resize(static_cast<std::size_t>(k));
    for (auto& band : bands_) band.clear();
    for (std::size_t i = 0; i < points.size(); ++i)
      bands_[static_cast<std::size_t>(labels.at<int>(static_cast<int>(i)))].push_back(points[i]);
    bool complete = true;
    const std::size_t start = out.size();
    for (const auto& band : bands_) {
      const BoxFit f = fit_box(band, size, false, eye);
      out.push_back({cls, {f.base.x(), f.base.y(), f.base.z()}, f.yaw, f.complete});
      complete = complete && f.complete;
    }
    if (complete) {
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(first), out.begin() + static_cast<std::ptrdiff_t>(start));
      return true;
    }
    if (first_tried == first) first_tried = out.size();
  }
  out.resize(first_tried);  // none complete: the nearest count's fits
  return true;
}

void CameraDetector::segment(const CameraImage& image) {
  segmenter_.segment(image.rgb.data(), image.width, image.height, segmentation_);
}

void CameraDetector::fit(const CameraImage& image, std::vector<world::Detection>& out) {
  out.clear();
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
      const std::string& cls = segmenter_.colours()[blob.colour].label;
      const BoxFit f = fit_box(pts, info.size, false, eye);
      if (!f.complete && split_touching(pts, info.size, eye, image.intrinsics.fx, cls, out)) continue;
      out.push_back({cls, {f.base.x(), f.base.y(), f.base.z()}, f.yaw, f.complete});
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
