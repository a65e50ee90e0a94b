// The depth camera's noise model (world::DepthNoise, docs/perception.md) applied to a
// clean metric depth image: dropouts at depth edges, then Gaussian noise of standard
// deviation a + b z², then rounding to whole quanta. Pixels reading 0 (no depth) stay 0;
// a noisy depth never goes below 0 (it reads 0 then). Edges are found on the clean image.
// The Gaussian deviates are a window of a fixed table of 2^20 unit normals starting at a
// random offset each frame (pixel i reads entry offset + i mod 2^20), so a frame's
// deviates are read in order and independent up to 2^20 pixels (a larger image repeats
// them); an edge pixel's dropout coin is a 24-bit uniform from a
// hash of its index and the frame's seed. One draw of `rng` a frame.
//
// Invariants: the same `rng` state gives the same image, whatever the CPU (the AVX2 and
// the baseline code do the same integer and float operations); no pixel's draws depend
// on another's, so the loops are branch-free and vectorised; no allocation once `noisy`
// has the image's size.
#pragma once

#include <random>
#include <vector>

#include "rtamp/world/camera.hpp"

namespace rtamp::sim {

// Best: AVX2 where the CPU has it; Baseline: x86-64's baseline code (the same image).
enum class Simd { Best, Baseline };

// `clean`: width*height metres, row-major, 0 = no reading. `noisy` is resized to it.
void apply_depth_noise(const std::vector<float>& clean, std::vector<float>& noisy, int width, int height,
                       const world::DepthNoise& noise, std::mt19937_64& rng, Simd simd = Simd::Best);

}  // namespace rtamp::sim
