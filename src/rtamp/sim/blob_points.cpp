#include "rtamp/sim/blob_points.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rtamp::sim {
namespace {

int find(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    i = parent[static_cast<std::size_t>(i)];
  }
  return i;
}

// The median of nine, branch-free: Devillard's 19 compare-exchanges (checked against a sort
// on every permutation of nine). Readings are noisy, so a sort's branches mispredict.
inline void sort2(float& a, float& b) {
  const float lo = std::min(a, b), hi = std::max(a, b);
  a = lo, b = hi;
}
float median9(float p[9]) {
  sort2(p[1], p[2]), sort2(p[4], p[5]), sort2(p[7], p[8]);
  sort2(p[0], p[1]), sort2(p[3], p[4]), sort2(p[6], p[7]);
  sort2(p[1], p[2]), sort2(p[4], p[5]), sort2(p[7], p[8]);
  sort2(p[0], p[3]), sort2(p[5], p[8]), sort2(p[4], p[7]);
  sort2(p[3], p[6]), sort2(p[1], p[4]), sort2(p[2], p[5]);
  sort2(p[4], p[7]), sort2(p[4], p[2]), sort2(p[6], p[4]);
  sort2(p[4], p[2]);
  return p[4];
}

double quantile(std::vector<double> v, double q) {
  const auto k = static_cast<std::ptrdiff_t>(std::floor(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

}  // namespace

std::vector<std::vector<Eigen::Vector3d>> blob_points(const ColourBlob& blob, const std::vector<float>& depth, int width,
                                                      const Intrinsics& K, const Extrinsics& E,
                                                      const BlobPointsOptions& options) {
  // The blob's pixels with a reading, ascending (the blob's order), and their depths.
  std::vector<std::int32_t> pix;
  std::vector<float> raw;
  for (std::int32_t i : blob.pixels) {
    const float d = depth[static_cast<std::size_t>(i)];
    if (d <= 0) continue;
    pix.push_back(i);
    raw.push_back(d);
  }
  if (pix.empty()) return {};
  // The blob's bounding box, grown by the smoothing radius, as a grid of indices into pix
  // (-1: not the blob's, no reading, or outside the box), so a window needs no bounds check.
  const int radius = options.smooth_radius;
  int u0 = width, u1 = -1, v0 = pix.front() / width, v1 = pix.back() / width;
  for (std::int32_t i : pix) u0 = std::min(u0, i % width), u1 = std::max(u1, i % width);
  const int bw = u1 - u0 + 1 + 2 * radius, bh = v1 - v0 + 1 + 2 * radius;
  std::vector<int> grid(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh), -1);
  const auto cell = [&](int u, int v) {
    return static_cast<std::size_t>(v - v0 + radius) * static_cast<std::size_t>(bw) + static_cast<std::size_t>(u - u0 + radius);
  };
  for (std::size_t a = 0; a < pix.size(); ++a) grid[cell(pix[a] % width, pix[a] / width)] = static_cast<int>(a);
  const auto at = [&](int u, int v) {
    if (u < u0 || u > u1 || v < v0 || v > v1) return -1;
    return grid[cell(u, v)];
  };
  // Each depth replaced by the median of the blob's readings in the window around it (the
  // noise is independent per pixel; the blob's own pixels only, so other surfaces do not
  // mix in), then the point's height. The median is the middle (upper middle) of the
  // sorted window. The height of the point at depth d on pixel (u, v)'s ray is
  // eye_z + d (gu (u - cx) + gv (v - cy) + g1): the third row of R^T applied to the
  // back-projected point.
  const Eigen::Vector3d eye = E.to_world(Eigen::Vector3d::Zero());
  const double gu = E.R(0, 2) / K.fx, gv = E.R(1, 2) / K.fy, g1 = E.R(2, 2);
  std::vector<double> z;
  std::vector<float> window(static_cast<std::size_t>((2 * radius + 1) * (2 * radius + 1)));
  z.reserve(pix.size());
  double mean_depth = 0;
  for (std::size_t a = 0; a < pix.size(); ++a) {
    const int u = pix[a] % width, v = pix[a] / width;
    if (radius == 1) {  // a whole 3x3 window (most pixels): the branch-free median
      const int* up = grid.data() + cell(u, v - 1);
      const int* mid = up + bw;
      const int* down = mid + bw;
      const int k[9] = {up[-1], up[0], up[1], mid[-1], mid[0], mid[1], down[-1], down[0], down[1]};
      if (std::min({k[0], k[1], k[2], k[3], k[4], k[5], k[6], k[7], k[8]}) >= 0) {
        float w[9];
        for (int i = 0; i < 9; ++i) w[i] = raw[static_cast<std::size_t>(k[i])];
        const double d = median9(w);
        z.push_back(eye.z() + d * (gu * (u - K.cx) + gv * (v - K.cy) + g1));
        mean_depth += d;
        continue;
      }
    }
    std::size_t n = 0;
    for (int dv = -radius; dv <= radius; ++dv) {
      const int* row = grid.data() + cell(u, v + dv);
      for (int du = -radius; du <= radius; ++du) {
        const int k = row[du];
        if (k < 0) continue;
        // Insertion into the sorted window.
        const float d = raw[static_cast<std::size_t>(k)];
        std::size_t j = n++;
        for (; j > 0 && window[j - 1] > d; --j) window[j] = window[j - 1];
        window[j] = d;
      }
    }
    const double d = window[n / 2];
    z.push_back(eye.z() + d * (gu * (u - K.cx) + gv * (v - K.cy) + g1));
    mean_depth += d;
  }
  mean_depth /= static_cast<double>(pix.size());
  // The noise left after the median of (2r+1)^2 readings: about 1.25 sigma / (2r+1).
  const double sigma = (options.noise.a + options.noise.b * mean_depth * mean_depth) * 1.25 / (2 * radius + 1);
  // The top height and the top face's pixels.
  const double high = quantile(z, 0.9);
  std::vector<double> near_top;
  for (double h : z)
    if (h >= high - options.top_band - 3 * sigma) near_top.push_back(h);
  const double top = options.top ? *options.top : quantile(near_top, 0.5);
  const double band = options.top_band + 2.5 * sigma;
  std::vector<int> parent(pix.size(), -1);  // -1: not on the top face
  for (std::size_t a = 0; a < pix.size(); ++a)
    if (std::abs(z[a] - top) <= band) parent[a] = options.split ? static_cast<int>(a) : 0;
  if (options.split) {
    const auto join = [&](std::size_t a, int neighbour) {
      if (neighbour < 0 || parent[static_cast<std::size_t>(neighbour)] < 0) return;
      const auto b = static_cast<std::size_t>(neighbour);
      const int ra = find(parent, static_cast<int>(a)), rb = find(parent, static_cast<int>(b));
      if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    };
    for (std::size_t a = 0; a < pix.size(); ++a) {
      if (parent[a] < 0) continue;
      const int u = pix[a] % width, v = pix[a] / width;
      join(a, at(u + 1, v));
      join(a, at(u, v + 1));
      join(a, at(u + 1, v + 1));
      join(a, at(u - 1, v + 1));
    }
  }
  // Clusters of pixel indices (into pix), then each re-projected onto its own plane.
  std::vector<int> cluster_of_root(pix.size(), -1);
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t a = 0; a < pix.size(); ++a) {
    if (parent[a] < 0) continue;
    const auto r = static_cast<std::size_t>(options.split ? find(parent, static_cast<int>(a)) : 0);
    if (cluster_of_root[r] < 0) {
      cluster_of_root[r] = static_cast<int>(members.size());
      members.emplace_back();
    }
    members[static_cast<std::size_t>(cluster_of_root[r])].push_back(a);
  }
  std::vector<std::vector<Eigen::Vector3d>> clusters;
  for (const auto& m : members) {
    if (static_cast<int>(m.size()) < options.min_points) continue;
    std::vector<double> h;
    for (std::size_t a : m) h.push_back(z[a]);
    const double plane = options.top ? *options.top : quantile(h, 0.5);
    auto& out = clusters.emplace_back();
    out.reserve(m.size());
    for (std::size_t a : m) {
      const Eigen::Vector3d ray = E.R.transpose() * K.back_project(pix[a] % width, pix[a] / width, 1.0);
      if (std::abs(ray.z()) < 1e-9) continue;
      out.push_back(eye + ray * ((plane - eye.z()) / ray.z()));
    }
  }
  return clusters;
}

std::vector<std::vector<Eigen::Vector3d>> join_near(std::vector<std::vector<Eigen::Vector3d>> clusters, double max_gap) {
  const auto near = [&](const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
    for (const auto& p : a)
      for (const auto& q : b)
        if ((p - q).head<2>().squaredNorm() <= max_gap * max_gap) return true;
    return false;
  };
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t i = 0; i < clusters.size() && !joined; ++i)
      for (std::size_t j = i + 1; j < clusters.size() && !joined; ++j)
        if (near(clusters[i], clusters[j])) {
          clusters[i].insert(clusters[i].end(), clusters[j].begin(), clusters[j].end());
          clusters.erase(clusters.begin() + static_cast<std::ptrdiff_t>(j));
          joined = true;
        }
  }
  return clusters;
}

}  // namespace rtamp::sim
