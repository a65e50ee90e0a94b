#include "rtamp/sim/depth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtamp::sim {

namespace {

// 2^16 unit normals (drawn once by std::normal_distribution, then shifted and scaled to
// mean 0 and variance 1 exactly).
const double* normal_table() {
  static const std::vector<double> t = [] {
    std::vector<double> v(1u << 16);
    std::mt19937_64 g(20261204);
    std::normal_distribution<double> n;
    double mean = 0, sq = 0;
    for (double& x : v) x = n(g), mean += x;
    mean /= static_cast<double>(v.size());
    for (double& x : v) x -= mean, sq += x * x;
    const double sd = std::sqrt(sq / static_cast<double>(v.size()));
    for (double& x : v) x /= sd;
    return v;
  }();
  return t.data();
}

// Standard normal deviates, fast: table entries indexed by xorshift64*. A
// std::normal_distribution on mt19937_64 per pixel cost ~20 ns; this ~2 ns.
class FastGauss {
 public:
  explicit FastGauss(std::uint64_t seed) : s_(seed | 1), table_(normal_table()) {}
  double operator()() {
    s_ ^= s_ >> 12, s_ ^= s_ << 25, s_ ^= s_ >> 27;
    return table_[static_cast<std::size_t>((s_ * 2685821657736338717ULL) >> 48)];
  }

 private:
  std::uint64_t s_;
  const double* table_;
};

}  // namespace

void apply_depth_noise(const std::vector<float>& clean, std::vector<float>& noisy, int width, int height,
                       const world::DepthNoise& noise, std::mt19937_64& rng) {
  noisy.resize(clean.size());
  std::bernoulli_distribution drop(noise.edge_dropout);
  FastGauss gauss(rng());
  const double quantum = noise.quantum_mm / 1000, jump = world::DepthNoise::kEdgeJump;
  const bool dropouts = noise.edge_dropout > 0;
  // A depth edge: a 4-neighbour in the image without a reading, or more than kEdgeJump
  // nearer or farther. Bitwise, not short-circuit, so the loops below are branch-free (this
  // file is compiled with -fno-trapping-math, which lets GCC vectorise them; the values are
  // the same).
  const auto far = [jump](double z, double other) { return (other <= 0) | (std::abs(other - z) > jump); };
  constexpr int kChunk = 64;
  for (int y = 0; y < height; ++y) {
    const float* row = clean.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    // A missing row or column: the pixel itself, which is never far from itself.
    const float* up = y > 0 ? row - width : row;
    const float* down = y + 1 < height ? row + width : row;
    float* out = noisy.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    for (int x0 = 0; x0 < width; x0 += kChunk) {
      const int x1 = std::min(width, x0 + kChunk);
      unsigned char edge[kChunk];
      const auto edge_at = [&](int x) {
        const double z = row[x];
        return static_cast<unsigned char>((x > 0 && far(z, row[x - 1])) || (x + 1 < width && far(z, row[x + 1])) ||
                                          far(z, up[x]) || far(z, down[x]));
      };
      const int i0 = std::max(x0, 1), i1 = std::min(x1, width - 1);  // the columns with both neighbours
      for (int x = i0; x < i1; ++x) {
        const double z = row[x];
        edge[x - x0] = static_cast<unsigned char>(far(z, row[x - 1]) | far(z, row[x + 1]) | far(z, up[x]) | far(z, down[x]));
      }
      if (x0 == 0) edge[0] = edge_at(0);
      if (x1 == width && width > 1) edge[x1 - 1 - x0] = edge_at(width - 1);
      // The draws, in raster order: an edge pixel's coin, then a kept pixel's deviate.
      double deviate[kChunk];
      unsigned char kept[kChunk];
      for (int x = x0; x < x1; ++x) {
        deviate[x - x0] = 0;
        kept[x - x0] = 0;
        if (row[x] <= 0 || (dropouts && edge[x - x0] && drop(rng))) continue;
        deviate[x - x0] = gauss();
        kept[x - x0] = 1;
      }
      // The noise and rounding, branch-free (vectorised). Round half up: floor(v / quantum
      // + 0.5) by adding and taking away 2^52 (exact below 2^52; std::floor and the int64
      // conversion do not vectorise on x86-64's baseline), the double that truncating
      // through int64 gives (v > 0 where it is kept).
      constexpr double kTwo52 = 4503599627370496.0;
      for (int x = x0; x < x1; ++x) {
        const double z = row[x];
        const double v = z + (noise.a + noise.b * z * z) * deviate[x - x0];
        const double q = v / quantum + 0.5;
        const double t = (q + kTwo52) - kTwo52;
        const double rounded = (t - (t > q ? 1.0 : 0.0)) * quantum;
        const double w = quantum > 0 ? rounded : v;
        out[x] = ((kept[x - x0] != 0) & (v > 0)) ? static_cast<float>(w) : 0.0f;
      }
    }
  }
}

}  // namespace rtamp::sim
