// Perception: what the robot believes is where. Reads body poses from the simulation
// and maps them to symbolic locations with world::Geometry — the same geometric
// abstraction the planner uses to read a scenario (paper Section II's partition of the
// workspace into regions; Section V's camera + segmentation replaced by ground truth
// plus optional noise).
//
// Rules: an object's observed point is the centre of its base (body origin minus half
// its height along world z); a held object is "in hand" (location kInHand); a
// container's location is the region under its position; containers are located with
// their CURRENT poses (moved, added, removed trays are tracked). With noise on, each
// observed position gets independent Gaussian noise (sigma per axis in x, y) and each
// thing is missed with probability miss_probability; missed things are absent from
// the placement. The random stream is seeded: same seed, same observations.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/placement.hpp"

namespace rtamp::sim {

inline constexpr const char* kInHand = "hand";

struct PerceptionOptions {
  double position_sigma = 0;    // m, standard deviation of x and y noise
  double miss_probability = 0;  // chance a present thing is not detected
  std::uint64_t seed = 1;
};

struct Observation {
  std::string name;
  std::string cls;
  bool container = false;
  bool detected = true;
  world::Vec3 position{};  // centre of its base, as observed (noise included)
  std::string location;    // region, container, kInHand or world::kNoLocation
};

struct Percept {
  double time = 0;
  std::vector<Observation> things;  // present things in model order (detected or not)
  // Detected things only.
  world::Placement placement() const;
  const Observation* find(const std::string& name) const;
};

class Perception {
 public:
  explicit Perception(const Simulation& sim, PerceptionOptions options = {});
  Percept observe();
  // The same into `out`, reusing its storage.
  void observe(Percept& out);
  const PerceptionOptions& options() const { return options_; }

 private:
  const Simulation& sim_;
  PerceptionOptions options_;
  std::mt19937_64 rng_;
  world::Geometry geometry_;
  std::vector<std::string> known_containers_;
};

}  // namespace rtamp::sim
