// Scenarios built in code for the sim tests: the paper's "3-block" and "3-block + tray"
// layouts (Section V) in front of a UR5 at the origin. Independent of world's loader.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::sim::testing {

inline world::Scenario three_block(bool with_tray = false) {
  world::Scenario s;
  s.name = with_tray ? "3-block-tray" : "3-block";
  s.regions.push_back({"r1", {0.45, -0.30, 0}, {0.24, 0.24, 0}, 8, {}});
  s.regions.push_back({"r2", {0.45, 0.30, 0}, {0.24, 0.24, 0}, 8, {}});
  if (with_tray) {
    s.containers.push_back({"r3", "tray", {0.62, -0.05, 0}, {0.24, 0.16, 0.03}, 4, {}});
  } else {
    s.regions.push_back({"r3", {0.62, 0.0, 0}, {0.2, 0.2, 0}, 8, {}});
  }
  s.objects.push_back({"o1", "block", {0.40, -0.36, 0}, {0.04, 0.04, 0.04}, {}});
  s.objects.push_back({"o2", "block", {0.50, -0.30, 0}, {0.04, 0.04, 0.04}, {}});
  s.objects.push_back({"o3", "block", {0.40, -0.24, 0}, {0.04, 0.04, 0.04}, {}});
  return s;
}

// How many of camera_scene's seeds (1..N) the static-scene tests run: 12, or
// RTAMP_CAMERA_SCENES=N to look wider by hand.
inline std::uint64_t camera_scene_count() {
  const char* env = std::getenv("RTAMP_CAMERA_SCENES");
  const std::uint64_t n = env ? std::strtoull(env, nullptr, 10) : 0;
  return n > 0 ? n : 12;
}

// The camera tests' scenes: 2-5 regions on a line, 1-8 blocks, 0-2 trays (with blocks on
// them), varied by the seed.
inline world::Scenario camera_scene(std::uint64_t seed) {
  world::GeneratorOptions g;
  g.seed = seed;
  g.regions = 2 + static_cast<int>(seed % 4);
  g.objects = 1 + static_cast<int>((seed * 5) % 8);
  g.containers = std::min<int>(static_cast<int>(seed % 3), g.regions - 1);
  g.layout = world::GeneratorOptions::Layout::Line;
  return world::generate_scenario(g);
}

}  // namespace rtamp::sim::testing
