// The depth camera's noise model (world::DepthNoise, docs/perception.md) applied to a
// clean metric depth image: dropouts at depth edges, then Gaussian noise of standard
// deviation a + b z², then rounding to whole quanta. Pixels reading 0 (no depth) stay 0;
// a noisy depth never goes below 0 (it reads 0 then). Edges are found on the clean image.
// The Gaussian deviates are entries of a fixed table of 2^16 unit normals picked by a
// fast generator seeded from `rng` (per-pixel std::normal_distribution cost most of a
// frame's budget; docs/benchmarks.md "Camera frames"); the dropouts' coin is `rng`'s.
//
// Invariants: the same `rng` state gives the same image; no allocation once `noisy` has
// the image's size. The edges are found branch-free a row chunk at a time (vectorised);
// the draws keep one order (pixels in raster order: an edge pixel's coin, then a kept
// pixel's deviate), so a seed gives the images it gave when each pixel was done in turn.
#pragma once

#include <random>
#include <vector>

#include "rtamp/world/camera.hpp"

namespace rtamp::sim {

// `clean`: width*height metres, row-major, 0 = no reading. `noisy` is resized to it.
void apply_depth_noise(const std::vector<float>& clean, std::vector<float>& noisy, int width, int height,
                       const world::DepthNoise& noise, std::mt19937_64& rng);

}  // namespace rtamp::sim
