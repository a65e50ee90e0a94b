#include "rtamp/sim/perception.hpp"

#include <algorithm>

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

Perception::Perception(const Simulation& sim, PerceptionOptions options)
    : sim_(sim), options_(options), rng_(options.seed), geometry_(sim.scenario().regions, {}) {}

Percept Perception::observe() {
  Percept p;
  observe(p);
  return p;
}

void Perception::observe(Percept& out) {
  out.time = sim_.time();
  out.things.clear();
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
