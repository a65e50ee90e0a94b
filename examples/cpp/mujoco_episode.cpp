// One episode of the reactive loop (the paper's Algorithm 1) on the simulated UR5 in
// MuJoCo, through episode::run_episode: plan the scenario's LTL task, execute it as a
// behavior tree on the physics, replan when the scenario's person intervenes
// (docs/library.md). The scenario is a built-in name or a YAML file (default 3-block).
// Exit 0 iff the episode succeeds.
// Build against the installed package with its MuJoCo component:
// find_package(rtamp COMPONENTS mujoco) and rtamp::rtamp_mujoco, or
// `c++ -std=c++20 mujoco_episode.cpp $(pkg-config --cflags --libs rtamp-mujoco)`.
#include <iostream>

#include "rtamp/episode/episode.hpp"
#include "rtamp/robot/ompl_logging.hpp"
#include "rtamp/sim/mujoco_logging.hpp"
#include "rtamp/world/scenario_io.hpp"

int main(int argc, char** argv) {
  rtamp::sim::install_mujoco_log_handler();  // no MUJOCO_LOG.TXT: warnings are counted in mjData
  rtamp::robot::quiet_ompl_logging();
  const rtamp::world::Scenario scenario = rtamp::world::load_scenario(argc > 1 ? argv[1] : "3-block");
  rtamp::episode::EpisodeOptions options;  // MuJoCo world, A* with experience, the scenario's operator
  options.outputs.timeline = [](const std::string& line) { std::cout << line << "\n"; };
  const rtamp::episode::EpisodeMetrics m = rtamp::episode::run_episode(scenario, options);
  std::cout << scenario.name << ": " << (m.success ? "success" : "failure") << " (" << m.reason << "), "
            << m.actions_succeeded << " actions, " << m.world_time << " s simulated\n";
  return m.success ? 0 : 1;
}
