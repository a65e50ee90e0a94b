#include "rtamp/sim/depth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtamp::sim {

namespace {

// Standard normal deviates, fast: Marsaglia's polar method on xorshift64* (seeded from
// the caller's generator once per image; std::normal_distribution on mt19937_64 cost
// ~30 ns a pixel, the whole budget of a frame at 640x480).
class FastGauss {
 public:
  explicit FastGauss(std::uint64_t seed) : s_(seed | 1) {}
  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u, v, q;
    do {
      u = uniform(), v = uniform();
      q = u * u + v * v;
    } while (q >= 1 || q == 0);
    const double f = std::sqrt(-2 * std::log(q) / q);
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }

 private:
  double uniform() {  // in (-1, 1)
    s_ ^= s_ >> 12, s_ ^= s_ << 25, s_ ^= s_ >> 27;
    return static_cast<double>((s_ * 2685821657736338717ULL) >> 11) * 0x1.0p-52 - 1;
  }
  std::uint64_t s_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace

void apply_depth_noise(std::vector<float>& depth, int width, int height, const world::DepthNoise& noise,
                       std::mt19937_64& rng) {
  const std::vector<float> clean = depth;
  auto at = [&](int x, int y) { return clean[static_cast<std::size_t>(y) * width + x]; };
  std::bernoulli_distribution drop(noise.edge_dropout);
  FastGauss gauss(rng());
  const double quantum = noise.quantum_mm / 1000;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float& d = depth[static_cast<std::size_t>(y) * width + x];
      const double z = d;
      if (z <= 0) continue;
      bool edge = false;
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= width || ny[k] >= height) continue;
        const double n = at(nx[k], ny[k]);
        edge = edge || n <= 0 || std::abs(n - z) > world::DepthNoise::kEdgeJump;
      }
      if (edge && noise.edge_dropout > 0 && drop(rng)) {
        d = 0;
        continue;
      }
      double v = z + (noise.a + noise.b * z * z) * gauss();
      if (quantum > 0) v = std::round(v / quantum) * quantum;
      d = static_cast<float>(std::max(v, 0.0));
    }
  }
}

}  // namespace rtamp::sim
