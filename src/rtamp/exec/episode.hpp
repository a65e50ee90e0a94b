// One episode of the reactive loop — the paper's Algorithm 1 on the simulated
// UR5 (Sections III.A and V): perceive every tick; if objects were only
// relocated and some subtree can handle the new state, do nothing more; if
// things were added or removed, update the transition system; otherwise replan
// with experience and reconfigure the behavior tree. The planner runs on a
// worker thread while the tree keeps ticking and the arm keeps moving; its
// measured wall time is charged to simulated time (a plan is used only once
// the simulation has advanced by that much since the request).
//
// The task is finished when every step of the tree is done and a plan from
// the perceived state needs no move: its prefix is empty and its cycle only
// stays (for F G p: p holds and nothing is left to do). Plans whose accepting
// cycle has moves (patrolling) run until max_time (reported as "cycle").
// The episode log (JSON Lines) records every tick's perceived placement,
// actions started and finished, interventions, plans and tree changes; it is
// written even when the episode fails or throws.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/plan/search.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

struct EpisodeOptions {
  plan::Algorithm algorithm = plan::Algorithm::AStarExperience;
  std::string cost = "euclid";                   // planner cost model: euclid | region | unit | ik
  ConditionMode conditions = ConditionMode::Action;
  Reconfiguration reconfiguration = Reconfiguration::Online;
  std::uint64_t seed = 1;
  double max_time = 900;          // s of simulated time before giving up
  double tick_period = 0.02;      // s of simulated time between BT ticks (50 Hz)
  bool randomize_initial = false; // shuffle objects inside their initial locations (seeded)
  bool scripted_operator = true;  // apply the scenario's `operator:` interventions
  // One extra random intervention of this kind (relocate / add / remove) on a
  // random present block, at a uniform random time in change_window (seeded).
  std::optional<world::Intervention::Kind> random_change;
  double change_window_begin = 2, change_window_end = 20;  // s; both built-in tasks take longer
  // The episode ends (unsuccessfully, with the last failure as reason) after
  // this many failed moves without a successful one in between.
  int max_consecutive_failures = 5;
  // A thing perceived outside every region and container keeps its last known
  // location this long (s of simulated time); after that the episode ends.
  double outside_grace = 3;
  std::string log_path;      // JSON Lines episode log; empty: none
  std::string tree_dir;      // BehaviorTree.CPP XML of the tree after each change; empty: none
  std::string video_path;    // MP4 of the run; empty: none
  // Readable timeline lines as they happen (nullptr: quiet).
  std::function<void(const std::string&)> timeline;
};

struct EpisodeMetrics {
  bool success = false;
  std::string reason;              // why it ended ("task done", "no plan: ...", "time limit", ...)
  double first_plan_seconds = 0;   // wall time of the first plan
  double replan_seconds = 0;       // total wall time of replans
  int replans = 0;
  std::size_t tree_changes = 0;    // subtrees inserted + removed, over the episode
  double completion_time = 0;      // simulated seconds until the task was done
  double motion_cost = 0;          // tool path length travelled (m), summed over every physics step
  int interventions = 0;
  int actions_succeeded = 0, actions_failed = 0;
  double wall_seconds = 0;
  double real_time_factor = 0;     // simulated / wall time
  std::uint64_t seed = 0;
};

EpisodeMetrics run_episode(const world::Scenario& scenario, const EpisodeOptions& options);

nlohmann::json to_json(const EpisodeMetrics& m);

}  // namespace rtamp::exec
