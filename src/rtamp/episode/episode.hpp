// One episode of the reactive loop (exec::ReactiveLoop, the paper's Algorithm
// 1) on a scenario, in a world of the user's choice — the simulated UR5 in
// MuJoCo (SimWorld) or the symbolic world (exec::SymbolicWorld, no physics,
// milliseconds an episode) — with the standard observers attached: the JSON
// Lines log, the readable timeline, tree dumps and (MuJoCo) video. This is
// what `rtamp run` and `rtamp batch` call; programs that bring their own world
// use exec::ReactiveLoop directly.
//
// Output files are opened (tree directory checked, video encoder started)
// before the episode starts; a bad path is an rtamp::Error, thrown before
// anything runs. Errors inside the episode end it with EndReason::Error and a
// complete log.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "rtamp/exec/episode_metrics.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/plan/search.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

enum class WorldKind { MuJoCo, Symbolic };
const char* to_string(WorldKind w);

struct EpisodeOptions {
  WorldKind world = WorldKind::MuJoCo;
  plan::Algorithm algorithm = plan::Algorithm::AStarExperience;
  std::string cost = "euclid";  // planner cost model: euclid | region | unit | ik
  exec::ConditionMode conditions = exec::ConditionMode::Action;
  exec::Reconfiguration reconfiguration = exec::Reconfiguration::Online;
  exec::PlanningMode planning = exec::PlanningMode::Worker;
  std::uint64_t seed = 1;
  double max_time = 900;          // s of world time before giving up
  double tick_period = 0.02;      // s between BT ticks (MuJoCo: 50 Hz)
  int cycles = 0;                 // recurring tasks: succeed after this many cycles
  bool randomize_initial = false; // shuffle objects inside their initial locations (seeded)
  bool scripted_operator = true;  // apply the scenario's `operator:` interventions
  // One extra random intervention of this kind on a random present block, at
  // a uniform random time in change_window (seeded).
  std::optional<world::Intervention::Kind> random_change;
  double change_window_begin = 2, change_window_end = 20;
  double random_rate = 0;           // random interventions per second (every kind the world knows)
  double failure_probability = 0;   // symbolic world: chance that a move fails
  int max_consecutive_failures = 5;
  double outside_grace = 3;
  std::string log_path;    // JSON Lines episode log; empty: none
  std::string tree_dir;    // BehaviorTree.CPP XML of the tree after each change; empty: none
  std::string video_path;  // MP4 of the run (MuJoCo only); empty: none
  std::function<void(const std::string&)> timeline;  // readable lines as they happen; null: quiet
  const std::atomic<int>* interrupt = nullptr;       // nonzero: stop (EndReason::Interrupted)
};

using exec::EpisodeMetrics;

EpisodeMetrics run_episode(const world::Scenario& scenario, const EpisodeOptions& options);

}  // namespace rtamp::episode
