#include "rtamp/sim/depth_noise.hpp"

#include <algorithm>
#include <cmath>

namespace rtamp::sim {

void apply_depth_noise(std::vector<float>& depth, int width, int height, const world::DepthNoise& noise,
                       std::mt19937_64& rng) {
  const std::vector<float> clean = depth;
  auto at = [&](int x, int y) { return clean[static_cast<std::size_t>(y) * width + x]; };
  std::bernoulli_distribution drop(noise.edge_dropout);
  std::normal_distribution<double> gauss(0.0, 1.0);
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
      double v = z + (noise.a + noise.b * z * z) * gauss(rng);
      if (quantum > 0) v = std::round(v / quantum) * quantum;
      d = static_cast<float>(std::max(v, 0.0));
    }
  }
}

}  // namespace rtamp::sim
