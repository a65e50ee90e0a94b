#include "rtamp/sim/depth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtamp::sim {

namespace {

constexpr int kTableBits = 20;  // 2^20 normals, 4 MiB
constexpr std::size_t kTable = std::size_t{1} << kTableBits;
constexpr int kChunk = 64;  // pixels a step (the table's tail repeats this many of its head)

// 2^20 unit normals (drawn once by std::normal_distribution, then shifted and scaled to
// mean 0 and variance 1 exactly), then its first kChunk again, so that kChunk
// consecutive entries can be read from any start below 2^20.
const float* normal_table() {
  static const std::vector<float> t = [] {
    std::vector<double> v(kTable);
    std::mt19937_64 g(20261204);
    std::normal_distribution<double> n;
    double mean = 0, sq = 0;
    for (double& x : v) x = n(g), mean += x;
    mean /= static_cast<double>(v.size());
    for (double& x : v) x -= mean, sq += x * x;
    const double sd = std::sqrt(sq / static_cast<double>(v.size()));
    std::vector<float> f(kTable + kChunk);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<float>(v[i % kTable] / sd);
    return f;
  }();
  return t.data();
}

// A 32-bit integer hash (Chris Wellons' lowbias32): each output bit depends on every
// input bit. Two 32-bit multiplies, which vectorise.
inline std::uint32_t mix(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  return x ^ (x >> 16);
}

struct Frame {
  const float* clean;
  float* noisy;
  int width, height;
  float a, b, quantum, inverse_quantum, jump;
  std::uint32_t threshold;  // a 24-bit uniform below it drops an edge pixel
  std::uint32_t offset;     // pixel i's deviate is table entry (offset + i) mod 2^20
  std::uint32_t seed;       // of the coins
};

// The whole image, one row chunk at a time. Inlined into a baseline and an AVX2
// function: the same integer and float operations in the same order (no fused
// multiply-add), so the same values.
[[gnu::always_inline]] inline void noise_image(const Frame& f) {
  const float* table = normal_table();
  constexpr float kTwo23 = 8388608.0f;  // floats from 2^23 up are whole numbers
  const int width = f.width;
  for (int y = 0; y < f.height; ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    const float* row = f.clean + first;
    // A missing row: the pixel itself, which is never far from itself.
    const float* up = y > 0 ? row - width : row;
    const float* down = y + 1 < f.height ? row + width : row;
    float* out = f.noisy + first;
    for (int x0 = 0; x0 < width; x0 += kChunk) {
      const int n = std::min(width, x0 + kChunk) - x0;
      const float* r = row + x0;
      const auto at = static_cast<std::uint32_t>(first + static_cast<std::size_t>(x0));
      const float* deviate = table + ((f.offset + at) & (kTable - 1));
      // A depth edge: a 4-neighbour in the image without a reading, or more than
      // kEdgeJump nearer or farther (a missing column: the pixel itself); an edge pixel
      // drops out on its coin, a 24-bit uniform from a hash of its index. Then the
      // noise, and rounding half up to whole quanta: floor(q) for q = v / quantum + 0.5
      // >= 0 by adding and taking away 2^23 (exact below 2^23; above it q is whole).
      // Bitwise, not short-circuit, so the loop is branch-free and vectorises (this file
      // is compiled with -fno-trapping-math).
      for (int i = 0; i < n; ++i) {
        const int x = x0 + i;
        const float z = r[i];
        const float left = x > 0 ? r[i - 1] : z, right = x + 1 < width ? r[i + 1] : z;
        const auto far = [&](float o) { return (o <= 0.0f) | (std::abs(o - z) > f.jump); };
        const bool edge = far(left) | far(right) | far(up[x]) | far(down[x]);
        const bool coin = (mix((at + static_cast<std::uint32_t>(i)) ^ f.seed) >> 8) < f.threshold;
        const float v = z + (f.a + f.b * z * z) * deviate[i];
        const float q = v * f.inverse_quantum + 0.5f;
        const float t = q < kTwo23 ? (q + kTwo23) - kTwo23 : q;
        const float rounded = (t - (t > q ? 1.0f : 0.0f)) * f.quantum;
        const float w = f.quantum > 0 ? rounded : v;
        out[x] = ((z > 0.0f) & !(edge & coin) & (v > 0.0f)) ? w : 0.0f;
      }
    }
  }
}

void noise_baseline(const Frame& f) { noise_image(f); }
__attribute__((target("avx2"))) void noise_avx2(const Frame& f) { noise_image(f); }

}  // namespace

void apply_depth_noise(const std::vector<float>& clean, std::vector<float>& noisy, int width, int height,
                       const world::DepthNoise& noise, std::mt19937_64& rng, Simd simd) {
  noisy.resize(clean.size());
  Frame f{};
  f.clean = clean.data();
  f.noisy = noisy.data();
  f.width = width;
  f.height = height;
  f.a = static_cast<float>(noise.a);
  f.b = static_cast<float>(noise.b);
  f.quantum = static_cast<float>(noise.quantum_mm / 1000);
  f.inverse_quantum = noise.quantum_mm > 0 ? static_cast<float>(1000 / noise.quantum_mm) : 0.0f;
  f.jump = static_cast<float>(world::DepthNoise::kEdgeJump);
  f.threshold = static_cast<std::uint32_t>(std::ldexp(std::clamp(noise.edge_dropout, 0.0, 1.0), 24));
  const std::uint64_t draw = rng();
  f.offset = static_cast<std::uint32_t>(draw);
  f.seed = static_cast<std::uint32_t>(draw >> 32);
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && simd == Simd::Best)
    noise_avx2(f);
  else
    noise_baseline(f);
}

}  // namespace rtamp::sim
