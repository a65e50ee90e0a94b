// Perception: what the robot believes is where, from one of two sources. `Truth` reads
// body poses from the simulation and maps them to symbolic locations with
// world::Geometry — the same geometric abstraction the planner uses to read a scenario
// (paper Section II's partition of the workspace into regions) — with optional noise.
// `Camera` sees as the paper's robot did (Section V): one or more of the scenario's
// cameras, each rendered at its own rate of world time (advance()), segmented and fitted
// from pixels, and kept in one world::Belief (camera_perception.hpp); a percept then lists the believed
// things at their believed poses, under the belief's names (a thing a person added is
// named by the belief, e.g. "block_seen1").
//
// Truth's rules: an object's observed point is the centre of its base (body origin minus half
// its height along world z); a held object is "in hand" (location kInHand); a
// container's location is the region under its position; containers are located with
// their CURRENT poses (moved, added, removed trays are tracked). With noise on, each
// observed position gets independent Gaussian noise (sigma per axis in x, y) and each
// thing is missed with probability miss_probability; missed things are absent from
// the placement. The random stream is seeded: same seed, same observations.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/belief.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/placement.hpp"

namespace rtamp::sim {

inline constexpr const char* kInHand = "hand";

enum class PerceptionSource { Truth, Camera };
// "truth" / "camera"; parse throws rtamp::Error naming the word.
const char* to_string(PerceptionSource s);
PerceptionSource parse_perception_source(const std::string& word);

struct PerceptionOptions {
  PerceptionSource source = PerceptionSource::Truth;
  double position_sigma = 0;    // Truth: m, standard deviation of x and y noise
  double miss_probability = 0;  // Truth: chance a present thing is not detected
  std::uint64_t seed = 1;
  // Camera: which of world::cameras_of(scenario) perceive; empty: the primary one.
  std::vector<std::string> cameras;
  world::BeliefOptions belief;      // Camera
};

class CameraPerception;

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
  // Throws rtamp::Error on an unknown or repeated camera, noise asked of the camera
  // source, or (camera) when offscreen rendering is unavailable.
  explicit Perception(const Simulation& sim, PerceptionOptions options = {});
  ~Perception();
  Perception(Perception&&) noexcept;
  Percept observe();
  // The same into `out`, reusing its storage.
  void observe(Percept& out);
  // Camera: takes a frame of each camera that is due at the simulation's time (in the
  // order the cameras were asked); call it after each step. Truth: nothing.
  void advance();
  const PerceptionOptions& options() const { return options_; }
  // Camera: the belief is confirming a change it has seen (world::Belief::confirming).
  // Truth: never.
  bool confirming() const;
  // The camera pipeline (nullptr for Truth).
  const CameraPerception* camera() const { return camera_.get(); }
  // Camera: `f` is called after each frame of any camera, with the pipeline (that frame's
  // camera, image and detections, and the belief after it).
  using FrameObserver = std::function<void(const CameraPerception&)>;
  void add_frame_observer(FrameObserver f) { frame_observers_.push_back(std::move(f)); }

 private:
  const Simulation& sim_;
  PerceptionOptions options_;
  std::mt19937_64 rng_;
  world::Geometry geometry_;
  std::vector<std::string> known_containers_;
  std::unique_ptr<CameraPerception> camera_;
  std::vector<FrameObserver> frame_observers_;
  std::vector<double> frame_period_, next_frame_;  // per perceiving camera
};

}  // namespace rtamp::sim
