// The worlds an episode can run in, by name: a registry of factories, each a
// name, a one-line description, the planning mode that suits it, and how to
// build the world for a scenario. It starts with rtamp's two — `mujoco` (the
// simulated UR5, SimWorld) and `symbolic` (exec::SymbolicWorld) — and a user
// adds theirs with register_world(); `rtamp run|batch|serve`, Python and
// batches then accept the name (the CLI's choices list what is registered when
// the command line is built). Registering a name again replaces its entry.
//
// Invariants: names are unique; find_world() accepts exactly the registered
// names and throws rtamp::Error with a did-you-mean otherwise; the registry is
// safe to read and extend from several threads.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

// What a world is built from besides the scenario and the episode's seed.
struct WorldSettings {
  double failure_probability = 0;  // worlds that draw move failures (symbolic): chance that a move fails
  // How the robot perceives (mujoco): "truth" (the simulation's poses) or "camera" (the
  // scenario's cameras and a belief, sim/perception.hpp).
  std::string perception = "truth";
  // With "camera": which of the scenario's cameras perceive, each at its own rate (empty:
  // the primary one). An unknown one is refused at "--perception-cameras" with its column.
  std::vector<std::string> perception_cameras;
};

// The cameras `w` asks to perceive through, checked against the scenario's (throws
// rtamp::Error at "--perception-cameras" on an unknown or repeated one, or any with
// perception other than "camera"); empty: the primary camera.
std::vector<std::string> perception_cameras(const world::Scenario& s, const WorldSettings& w);

// Builds the world for a scenario (throws rtamp::Error on bad settings, before anything runs).
using WorldFactory =
    std::function<std::unique_ptr<exec::World>(const world::Scenario&, std::uint64_t seed, const WorldSettings&)>;

struct WorldInfo {
  std::string name;
  std::string description;  // one line, no final period
  WorldFactory make;
  // How the loop plans in this world by default: a continuous world keeps
  // moving while the planner works (worker); a discrete-event world plans inline.
  exec::PlanningMode planning = exec::PlanningMode::Worker;
};

// Adds (or replaces, by name) a world. Throws rtamp::Error for an empty name or factory.
void register_world(WorldInfo info);
// A snapshot of the registry in registration order (mujoco, symbolic, then the user's).
std::vector<WorldInfo> worlds();
std::vector<std::string> world_names();
// The world named `name`; rtamp::Error "unknown world 'symbolik' (did you mean 'symbolic'?)" otherwise.
WorldInfo find_world(std::string_view name);

}  // namespace rtamp::episode
