#include "rtamp/episode/world_registry.hpp"

#include <algorithm>
#include <utility>

#include "rtamp/episode/sim_world.hpp"
#include "rtamp/exec/perception_errors.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/util/named_registry.hpp"
#include "rtamp/world/camera.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::episode {

namespace {

std::unique_ptr<exec::World> make_mujoco(const world::Scenario& s, std::uint64_t seed, const WorldSettings& w) {
  if (w.failure_probability != 0)
    throw Error("failure probability " + format_number(w.failure_probability) +
                ": the mujoco world's moves fail by physics alone (the option is for the symbolic world)");
  sim::SessionOptions so;
  so.seed = seed;
  so.perception.source = sim::parse_perception_source(w.perception);
  so.perception.cameras = perception_cameras(s, w);
  return std::make_unique<SimWorld>(s, so);
}

std::unique_ptr<exec::World> make_symbolic(const world::Scenario& s, std::uint64_t seed, const WorldSettings& w) {
  const sim::PerceptionSource source = sim::parse_perception_source(w.perception);
  exec::SymbolicWorldOptions so;
  so.seed = seed;
  so.failure_probability = w.failure_probability;
  auto world = std::make_unique<exec::SymbolicWorld>(s, so);
  if (source == sim::PerceptionSource::Truth) return world;
  // No camera to render: the errors the MuJoCo camera pipeline was measured to make.
  return std::make_unique<exec::PerceptionErrorWorld>(std::move(world), s, exec::camera_perception_errors(seed));
}

NamedRegistry<WorldInfo>& registry() {
  static NamedRegistry<WorldInfo> r({
      {"mujoco", "the simulated UR5 in MuJoCo", make_mujoco, exec::PlanningMode::Worker},
      {"symbolic", "a discrete-event world with no physics (milliseconds an episode)", make_symbolic,
       exec::PlanningMode::Inline},
  });
  return r;
}

}  // namespace

std::vector<std::string> perception_cameras(const world::Scenario& s, const WorldSettings& w) {
  if (w.perception != "camera" && !w.perception_cameras.empty())
    throw Error("the cameras perceive only with --perception camera", SourceLocation{"--perception-cameras", 1, 1});
  const std::vector<world::Camera> cameras = world::cameras_of(s);
  std::vector<std::string> out;
  int column = 1;
  for (const std::string& name : w.perception_cameras) {
    const SourceLocation where{"--perception-cameras", 1, column};
    if (std::find(out.begin(), out.end(), name) != out.end()) throw Error("camera '" + name + "' is listed twice", where);
    out.push_back(world::find_camera(cameras, name, where).name);
    column += static_cast<int>(name.size()) + 1;
  }
  return out;
}

void register_world(WorldInfo info) {
  if (info.name.empty() || !info.make) throw Error("a world needs a name and a factory");
  registry().add(std::move(info));
}

std::vector<WorldInfo> worlds() { return registry().entries(); }

std::vector<std::string> world_names() { return registry().names(); }

WorldInfo find_world(std::string_view name) {
  if (auto w = registry().find(name)) return *w;
  throw Error("unknown world " + world::quoted(name) + world::suggestion(name, world_names()));
}

}  // namespace rtamp::episode
