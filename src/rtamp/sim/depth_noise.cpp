#include "rtamp/sim/depth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <immintrin.h>

namespace rtamp::sim {

namespace {

constexpr int kTableBits = 12;  // 4096 floats: 16 KiB, in the L1 cache

// 2^12 unit normals (drawn once by std::normal_distribution, then shifted and scaled to
// mean 0 and variance 1 exactly).
const float* normal_table() {
  static const std::vector<float> t = [] {
    std::vector<double> v(1u << kTableBits);
    std::mt19937_64 g(20261204);
    std::normal_distribution<double> n;
    double mean = 0, sq = 0;
    for (double& x : v) x = n(g), mean += x;
    mean /= static_cast<double>(v.size());
    for (double& x : v) x -= mean, sq += x * x;
    const double sd = std::sqrt(sq / static_cast<double>(v.size()));
    std::vector<float> f(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) f[i] = static_cast<float>(v[i] / sd);
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
  std::uint32_t seed[3];    // of the pixel's own bits, its deviate, its coin
};

constexpr std::uint32_t kMask = (1u << kTableBits) - 1;
constexpr float kSqrtHalf = 0.70710678f;

// Pixel i's draws (none depends on another pixel's): its deviate, the sum of two table
// entries over sqrt 2 (a sum of normals is normal), and its coin (1: an edge there drops).
inline void draw(const Frame& f, const float* table, std::uint32_t i, float& deviate, unsigned char& coin) {
  const std::uint32_t own = mix(i ^ f.seed[0]);
  const std::uint32_t d = mix(own ^ f.seed[1]), c = mix(own ^ f.seed[2]);
  deviate = (table[d & kMask] + table[(d >> kTableBits) & kMask]) * kSqrtHalf;
  coin = static_cast<unsigned char>((c >> 8) < f.threshold);
}

// The draws of pixels first .. first + n - 1.
void draws(const Frame& f, std::uint32_t first, int n, float* deviate, unsigned char* coin) {
  const float* table = normal_table();
  for (int i = 0; i < n; ++i) draw(f, table, first + static_cast<std::uint32_t>(i), deviate[i], coin[i]);
}

// mix() of eight lanes.
__attribute__((target("avx2"))) inline __m256i mix8(__m256i x) {
  x = _mm256_xor_si256(x, _mm256_srli_epi32(x, 16));
  x = _mm256_mullo_epi32(x, _mm256_set1_epi32(0x7feb352d));
  x = _mm256_xor_si256(x, _mm256_srli_epi32(x, 15));
  x = _mm256_mullo_epi32(x, _mm256_set1_epi32(static_cast<int>(0x846ca68bU)));
  return _mm256_xor_si256(x, _mm256_srli_epi32(x, 16));
}

// The same, eight pixels at a time with AVX2's gathers (GCC does not gather on its own
// for generic x86-64): the same integer and float operations, so the same values.
__attribute__((target("avx2"))) void draws_avx2(const Frame& f, std::uint32_t first, int n, float* deviate,
                                                  unsigned char* coin) {
  const float* table = normal_table();
  const __m256i s0 = _mm256_set1_epi32(static_cast<int>(f.seed[0])), s1 = _mm256_set1_epi32(static_cast<int>(f.seed[1])),
                s2 = _mm256_set1_epi32(static_cast<int>(f.seed[2])), mask = _mm256_set1_epi32(kMask),
                threshold = _mm256_set1_epi32(static_cast<int>(f.threshold)), lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256i index = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(first + static_cast<std::uint32_t>(i))), lanes);
    const __m256i own = mix8(_mm256_xor_si256(index, s0));
    const __m256i d = mix8(_mm256_xor_si256(own, s1)), c = mix8(_mm256_xor_si256(own, s2));
    const __m256 t1 = _mm256_i32gather_ps(table, _mm256_and_si256(d, mask), 4);
    const __m256 t2 = _mm256_i32gather_ps(table, _mm256_and_si256(_mm256_srli_epi32(d, kTableBits), mask), 4);
    _mm256_storeu_ps(deviate + i, _mm256_mul_ps(_mm256_add_ps(t1, t2), _mm256_set1_ps(kSqrtHalf)));
    // c >> 8 and the threshold are below 2^25: the signed comparison is the unsigned one.
    const int drops = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(threshold, _mm256_srli_epi32(c, 8))));
    for (int k = 0; k < 8; ++k) coin[i + k] = static_cast<unsigned char>((drops >> k) & 1);
  }
  for (; i < n; ++i) draw(f, table, first + static_cast<std::uint32_t>(i), deviate[i], coin[i]);
}

// The whole image, one row chunk at a time, with the given draws. Inlined into a baseline
// and an AVX2 function: the same float operations in the same order (no fused
// multiply-add), so the same values.
template <class Draws>
[[gnu::always_inline]] inline void noise_image(const Frame& f, Draws&& draws) {
  constexpr int kChunk = 64;
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
      float deviate[kChunk];
      unsigned char coin[kChunk];
      const auto at = static_cast<std::uint32_t>(first + static_cast<std::size_t>(x0));
      draws(f, at, n, deviate, coin);
      // A depth edge: a 4-neighbour in the image without a reading, or more than
      // kEdgeJump nearer or farther (a missing column: the pixel itself). Then the noise,
      // and rounding half up to whole quanta: floor(q) for q = v / quantum + 0.5 >= 0 by
      // adding and taking away 2^23 (exact below 2^23; above it q is whole). Bitwise, not
      // short-circuit, so the loop is branch-free and vectorises (this file is compiled
      // with -fno-trapping-math).
      for (int i = 0; i < n; ++i) {
        const int x = x0 + i;
        const float z = r[i];
        const float left = x > 0 ? r[i - 1] : z, right = x + 1 < width ? r[i + 1] : z;
        const auto far = [&](float o) { return (o <= 0.0f) | (std::abs(o - z) > f.jump); };
        const bool edge = far(left) | far(right) | far(up[x]) | far(down[x]);
        const float v = z + (f.a + f.b * z * z) * deviate[i];
        const float q = v * f.inverse_quantum + 0.5f;
        const float t = q < kTwo23 ? (q + kTwo23) - kTwo23 : q;
        const float rounded = (t - (t > q ? 1.0f : 0.0f)) * f.quantum;
        const float w = f.quantum > 0 ? rounded : v;
        out[x] = (z > 0.0f) & ((edge & (coin[i] != 0)) == 0) & (v > 0.0f) ? w : 0.0f;
      }
    }
  }
}

void noise_baseline(const Frame& f) { noise_image(f, draws); }
__attribute__((target("avx2"))) void noise_avx2(const Frame& f) { noise_image(f, draws_avx2); }

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
  const std::uint64_t s0 = rng(), s1 = rng();
  f.seed[0] = static_cast<std::uint32_t>(s0);
  f.seed[1] = static_cast<std::uint32_t>(s0 >> 32);
  f.seed[2] = static_cast<std::uint32_t>(s1);
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && simd == Simd::Best)
    noise_avx2(f);
  else
    noise_baseline(f);
}

}  // namespace rtamp::sim
