// SplitMix64: a small seeded random stream whose numbers are the same on every
// platform and standard library (std::uniform_*_distribution are not), for
// everything rtamp draws that a test or a user must be able to reproduce: a
// person's random interventions, a symbolic world's move failures.
#pragma once

#include <cstdint>

namespace rtamp {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t state = 0) : state_(state) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // uniform in [0, 1)
  std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : next() % n; }   // in [0, n)

 private:
  std::uint64_t state_;
};

}  // namespace rtamp
