// The depth noise model against its definition: on two flat halves at 1 m and 2.5 m the
// sample standard deviation of the error is a + b z² (within 3 % over ~10^5 pixels),
// every reading is a whole number of quanta, the mean stays unbiased, and pixels read
// no depth only at the step between the halves, at about the edge dropout rate; the AVX2
// and the baseline code give the same image, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "rtamp/sim/depth_noise.hpp"

namespace rtamp::sim {
namespace {

TEST(DepthNoise, MatchesItsModel) {
  const int w = 400, h = 300;
  std::vector<float> depth(static_cast<std::size_t>(w) * h);
  auto clean = [&](int u) { return u < w / 2 ? 1.0 : 2.5; };
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) depth[static_cast<std::size_t>(v) * w + u] = static_cast<float>(clean(u));
  world::DepthNoise noise;
  noise.a = 0.001, noise.b = 0.002, noise.quantum_mm = 1, noise.edge_dropout = 0.5;
  std::mt19937_64 rng(7);
  const std::vector<float> truth = depth;
  apply_depth_noise(truth, depth, w, h, noise, rng);
  double sum[2] = {0, 0}, sq[2] = {0, 0};
  int n[2] = {0, 0}, dropped_inside = 0, dropped_edge = 0, not_quantised = 0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const double d = depth[static_cast<std::size_t>(v) * w + u];
      const bool edge = u == w / 2 - 1 || u == w / 2;
      if (d == 0) {
        (edge ? dropped_edge : dropped_inside)++;
        continue;
      }
      not_quantised += std::abs(d * 1000 - std::round(d * 1000)) > 1e-3;
      if (edge) continue;
      const int k = u < w / 2 ? 0 : 1;
      const double e = d - clean(u);
      sum[k] += e, sq[k] += e * e, ++n[k];
    }
  EXPECT_EQ(dropped_inside, 0);
  EXPECT_NEAR(dropped_edge, h, 0.2 * h);  // 2h edge pixels, half dropped
  EXPECT_EQ(not_quantised, 0);
  for (int k = 0; k < 2; ++k) {
    const double z = k == 0 ? 1.0 : 2.5, mean = sum[k] / n[k];
    const double sd = std::sqrt(sq[k] / n[k] - mean * mean);
    // Rounding to 1 mm adds a variance of 1/12 mm².
    const double model = std::sqrt(std::pow(noise.a + noise.b * z * z, 2) + 1e-6 / 12);
    EXPECT_NEAR(sd, model, 0.03 * model) << "z = " << z;
    EXPECT_LT(std::abs(mean), 4 * model / std::sqrt(n[k])) << "z = " << z;
  }
}

TEST(DepthNoise, TheVectorAndTheBaselineCodeGiveTheSameImage) {
  // Steps, holes and a width that is no multiple of 8 or 64 (the code's lanes and chunks).
  const int w = 203, h = 37;
  std::vector<float> clean(static_cast<std::size_t>(w) * h);
  std::mt19937_64 scene(3);
  std::uniform_real_distribution<float> depth(0.3f, 2.9f);
  for (std::size_t i = 0; i < clean.size(); ++i) clean[i] = i % 17 == 0 ? 0.0f : (i / 40) % 2 ? depth(scene) : 1.5f;
  world::DepthNoise noise;
  noise.edge_dropout = 0.37;
  for (double quantum : {0.0, 0.25, 1.0}) {
    noise.quantum_mm = quantum;
    std::mt19937_64 a(11), b(11);
    std::vector<float> best, baseline;
    apply_depth_noise(clean, best, w, h, noise, a, Simd::Best);
    apply_depth_noise(clean, baseline, w, h, noise, b, Simd::Baseline);
    ASSERT_EQ(best.size(), baseline.size());
    EXPECT_EQ(std::memcmp(best.data(), baseline.data(), best.size() * sizeof(float)), 0) << "quantum " << quantum;
    EXPECT_NE(best, clean);
  }
}

TEST(DepthNoise, NoReadingStaysNoReading) {
  const std::vector<float> none(64, 0.0f);
  std::vector<float> depth;
  std::mt19937_64 rng(1);
  apply_depth_noise(none, depth, 8, 8, world::DepthNoise{}, rng);
  ASSERT_EQ(depth.size(), none.size());
  for (float d : depth) EXPECT_EQ(d, 0.0f);
}

}  // namespace
}  // namespace rtamp::sim
