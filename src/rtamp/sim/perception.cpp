#include "rtamp/sim/perception.hpp"

#include <algorithm>

#include "rtamp/sim/camera_perception.hpp"
#include "rtamp/sim/colour_segmentation.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/camera.hpp"

namespace rtamp::sim {

world::Placement Percept::placement() const {
  world::Placement p;
  for (const auto& o : things)
    if (o.detected) p.set(o.name, o.location, o.cls, o.container);
  return p;
}

const Observation* Percept::find(const std::string& name) const {
  for (const auto& o : things)
    if (o.name == name) return &o;
  return nullptr;
}

const char* to_string(PerceptionSource s) { return s == PerceptionSource::Camera ? "camera" : "truth"; }

PerceptionSource parse_perception_source(const std::string& word) {
  if (word == "truth") return PerceptionSource::Truth;
  if (word == "camera") return PerceptionSource::Camera;
  throw Error("unknown perception '" + word + "' (truth or camera)");
}

Perception::Perception(const Simulation& sim, PerceptionOptions options)
    : sim_(sim), options_(options), rng_(options.seed), geometry_(sim.scenario().regions, {}) {
  if (options_.source != PerceptionSource::Camera) return;
  if (options_.position_sigma != 0 || options_.miss_probability != 0)
    throw Error("position noise and misses are for truth perception; a camera's errors are its own");
  check_scene_colours(sim.scenario());
  const std::vector<world::Camera> cameras = world::cameras_of(sim.scenario());
  for (const std::string& name : options_.cameras) world::find_camera(cameras, name, {});  // before any context
  camera_ = std::make_unique<CameraPerception>(
      sim, CameraPerceptionOptions{.cameras = options_.cameras, .belief = options_.belief, .seed = options_.seed});
  for (const world::Camera& c : camera_->cameras()) {
    frame_period_.push_back(1.0 / c.rate);
    next_frame_.push_back(sim.time());
  }
}

Perception::~Perception() = default;
Perception::Perception(Perception&&) noexcept = default;

void Perception::advance() {
  if (!camera_) return;
  for (std::size_t k = 0; k < next_frame_.size(); ++k) {
    if (sim_.time() + 1e-9 < next_frame_[k]) continue;
    camera_->frame(k);
    for (const FrameObserver& f : frame_observers_) f(*camera_);
    while (next_frame_[k] <= sim_.time() + 1e-9) next_frame_[k] += frame_period_[k];
  }
}

bool Perception::confirming() const { return camera_ && camera_->belief().confirming(); }

Percept Perception::observe() {
  Percept p;
  observe(p);
  return p;
}

void Perception::observe(Percept& out) {
  out.time = sim_.time();
  out.things.clear();
  if (camera_) {
    advance();
    const world::Placement p = camera_->belief().placement();
    for (const world::BelievedThing& t : camera_->belief().things()) {
      Observation o;
      o.name = t.name;
      o.cls = t.cls;
      o.container = t.container;
      o.position = t.base;
      o.location = p.things.at(t.name).location;
      if (o.location == "hand") o.location = kInHand;
      out.things.push_back(std::move(o));
    }
    return;
  }
  const bool noisy = options_.position_sigma > 0 || options_.miss_probability > 0;
  std::normal_distribution<double> noise(0.0, options_.position_sigma > 0 ? options_.position_sigma : 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto& things = sim_.things();
  auto observe_one = [&](const Thing& t, int i) {
    Observation o;
    o.name = t.name;
    o.cls = t.cls;
    o.container = t.container;
    auto pose = sim_.pose(i);
    const Eigen::Vector3d c = pose.translation();
    // Containers' body origin is the base centre; a block's is its centre.
    o.position = {c.x(), c.y(), t.container ? c.z() : c.z() - t.size[2] / 2};
    if (noisy) {
      if (options_.position_sigma > 0) {
        o.position[0] += noise(rng_);
        o.position[1] += noise(rng_);
      }
      if (options_.miss_probability > 0 && unit(rng_) < options_.miss_probability) o.detected = false;
    }
    return o;
  };
  // Containers first: their current poses define where they hold things.
  std::vector<std::string> present;
  for (std::size_t i = 0; i < things.size(); ++i) {
    const Thing& t = things[i];
    if (!t.container || !t.present || t.name.empty()) continue;
    Observation o = observe_one(t, static_cast<int>(i));
    present.push_back(t.name);
    world::Container c{t.name, t.cls, o.position, t.size, 8, {}};
    if (!geometry_.move_container(t.name, o.position)) geometry_.add_container(c);
    o.location = sim_.held() == static_cast<int>(i) ? std::string(kInHand) : geometry_.locate_region(o.position);
    out.things.push_back(std::move(o));
  }
  for (const auto& c : known_containers_)
    if (std::find(present.begin(), present.end(), c) == present.end()) geometry_.remove_container(c);
  known_containers_ = std::move(present);
  for (std::size_t i = 0; i < things.size(); ++i) {
    const Thing& t = things[i];
    if (t.container || !t.present || t.name.empty()) continue;
    Observation o = observe_one(t, static_cast<int>(i));
    o.location = sim_.held() == static_cast<int>(i) ? std::string(kInHand) : geometry_.locate(o.position);
    out.things.push_back(std::move(o));
  }
}

}  // namespace rtamp::sim
