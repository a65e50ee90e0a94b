#include "rtamp/sim/box_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace rtamp::sim {

BoxFit fit_box(const std::vector<Eigen::Vector3d>& points, const world::Vec3& size, bool container,
               const Eigen::Vector3d& eye, const BoxFitOptions& options) {
  BoxFit fit;
  if (points.size() < 3) return fit;
  // The top height: the 95th percentile of z (a few noisy points above do not lift it).
  std::vector<double> z;
  z.reserve(points.size());
  for (const auto& p : points) z.push_back(p.z());
  const auto k = static_cast<std::ptrdiff_t>(std::floor(0.95 * static_cast<double>(z.size() - 1)));
  std::nth_element(z.begin(), z.begin() + k, z.end());
  const double top = z[static_cast<std::size_t>(k)];
  std::vector<cv::Point2f> xy;  // millimetres: float precision is ample there
  xy.reserve(points.size());
  for (const auto& p : points)
    if (container || p.z() >= top - options.top_band)
      xy.emplace_back(static_cast<float>(p.x() * 1000), static_cast<float>(p.y() * 1000));
  fit.points = static_cast<int>(xy.size());
  if (xy.size() < 3) return fit;
  // The yaw from OpenCV's minimum-area rectangle (width along `angle` degrees); the sides
  // and centre from the points' extents along its axes, trimmed at each end by a share of
  // one row of points (about the square root of their number) so that a few noisy points
  // at the silhouette do not widen it (trimmed symmetrically, the midpoint stays unbiased).
  const cv::RotatedRect r = cv::minAreaRect(xy);
  double yaw = r.angle * std::numbers::pi / 180;
  const auto extent = [&](double angle, double& lo, double& hi) {
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<double> t;
    t.reserve(xy.size());
    for (const auto& p : xy) t.push_back((c * p.x + s * p.y) / 1000.0);
    const auto n = static_cast<std::ptrdiff_t>(t.size());
    const auto cut = static_cast<std::ptrdiff_t>(options.trim_rows * std::sqrt(static_cast<double>(n)));
    std::nth_element(t.begin(), t.begin() + cut, t.end());
    lo = t[static_cast<std::size_t>(cut)];
    std::nth_element(t.begin(), t.begin() + (n - 1 - cut), t.end());
    hi = t[static_cast<std::size_t>(n - 1 - cut)];
  };
  double lo_a, hi_a, lo_b, hi_b;
  extent(yaw, lo_a, hi_a);
  extent(yaw + std::numbers::pi / 2, lo_b, hi_b);
  // A row of points spans one pixel's footprint less than the face: half a spacing at each end.
  const double spacing = options.spacing > 0 ? options.spacing
                                             : std::sqrt((hi_a - lo_a) * (hi_b - lo_b) / static_cast<double>(xy.size()));
  lo_a -= spacing / 2, hi_a += spacing / 2, lo_b -= spacing / 2, hi_b += spacing / 2;
  // Which of the thing's sides lies along the rectangle's first axis.
  const double a = hi_a - lo_a, b = hi_b - lo_b;
  const bool swapped = std::abs(b - size[0]) + std::abs(a - size[1]) < std::abs(a - size[0]) + std::abs(b - size[1]);
  const double side_a = swapped ? size[1] : size[0], side_b = swapped ? size[0] : size[1];
  // Along each axis: the edge away from the camera is exact; the one towards it may carry the
  // top of the side face facing the camera. So the centre is one half side in from the far
  // edge, or the midpoint when the camera looks down between the edges.
  const auto centre = [&](double angle, double lo, double hi, double side, double& seen_ok) {
    const double e = std::cos(angle) * eye.x() + std::sin(angle) * eye.y();
    const double seen = hi - lo;
    if (e < lo) {
      seen_ok = seen >= side - options.tolerance && seen <= side + options.tolerance + options.side_bleed;
      return hi - side / 2;
    }
    if (e > hi) {
      seen_ok = seen >= side - options.tolerance && seen <= side + options.tolerance + options.side_bleed;
      return lo + side / 2;
    }
    seen_ok = std::abs(seen - side) <= options.tolerance;
    return (lo + hi) / 2;
  };
  double ok_a = 0, ok_b = 0;
  const double mid_a = centre(yaw, lo_a, hi_a, side_a, ok_a);
  const double mid_b = centre(yaw + std::numbers::pi / 2, lo_b, hi_b, side_b, ok_b);
  const double cx = std::cos(yaw) * mid_a - std::sin(yaw) * mid_b, cy = std::sin(yaw) * mid_a + std::cos(yaw) * mid_b;
  if (swapped) yaw += std::numbers::pi / 2;
  fit.yaw = std::remainder(yaw, std::numbers::pi);  // a box looks the same turned half a turn
  fit.seen_x = swapped ? b : a;
  fit.seen_y = swapped ? a : b;
  fit.base = {cx, cy, top - size[2]};
  fit.complete = ok_a > 0 && ok_b > 0;
  return fit;
}

}  // namespace rtamp::sim
