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
  // nearer or farther. Bitwise, not short-circuit, so the loop below is branch-free.
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
      for (int x = x0; x < x1; ++x) {
        const double z = row[x];
        const double left = row[x > 0 ? x - 1 : x], right = row[x + 1 < width ? x + 1 : x];
        edge[x - x0] = static_cast<unsigned char>(far(z, left) | far(z, right) | far(z, up[x]) | far(z, down[x]));
      }
      for (int x = x0; x < x1; ++x) {
        const double z = row[x];
        out[x] = row[x];
        if (z <= 0) continue;
        if (dropouts && edge[x - x0] && drop(rng)) {
          out[x] = 0;
          continue;
        }
        double v = z + (noise.a + noise.b * z * z) * gauss();
        if (v <= 0) {
          out[x] = 0;
          continue;
        }
        // Round half up by truncation (v > 0): std::round is a library call on x86-64's baseline.
        if (quantum > 0) v = static_cast<double>(static_cast<std::int64_t>(v / quantum + 0.5)) * quantum;
        out[x] = static_cast<float>(v);
      }
    }
  }
}

}  // namespace rtamp::sim
