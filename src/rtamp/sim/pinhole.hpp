// The pinhole camera model in OpenCV's convention (docs/perception.md): camera frame x
// right, y down, z forward; pixel (u, v) = column, row with the centre of the top-left
// pixel at (0, 0); u = fx x/z + cx, v = fy y/z + cy. Extrinsics map the world into the
// camera frame: p_cam = R p_world + t. No lens distortion (MuJoCo renders none).
#pragma once

#include <Eigen/Core>

namespace rtamp::sim {

struct Intrinsics {
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  // Pixel of a camera-frame point (z > 0).
  Eigen::Vector2d project(const Eigen::Vector3d& p) const { return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy}; }
  // Camera-frame point at pixel (u, v) and depth z along the optical axis.
  Eigen::Vector3d back_project(double u, double v, double z) const {
    return {(u - cx) / fx * z, (v - cy) / fy * z, z};
  }
};

struct Extrinsics {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // world -> camera
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_camera(const Eigen::Vector3d& w) const { return R * w + t; }
  Eigen::Vector3d to_world(const Eigen::Vector3d& c) const { return R.transpose() * (c - t); }
};

}  // namespace rtamp::sim
