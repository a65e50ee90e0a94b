// One episode of the reactive loop (exec::ReactiveLoop, the paper's Algorithm
// 1) on a scenario, in a world of the user's choice — the simulated UR5 in
// MuJoCo (SimWorld) or the symbolic world (exec::SymbolicWorld, no physics,
// milliseconds an episode) — with the standard observers attached: the JSON
// Lines log, the readable timeline, tree dumps and (MuJoCo) video. This is
// what `rtamp run` and `rtamp batch` call; programs that bring their own world
// use exec::ReactiveLoop directly.
//
// Every input (the task, the planner's names, the loop's numbers, the world's
// options) is checked before any output file is opened, and the outputs
// (log, tree directory, video encoder) before the episode starts: a bad one
// is an rtamp::Error, thrown before anything is written or runs. Errors
// inside the episode end it with EndReason::Error and a complete log; a
// video encoder that failed then throws its rtamp::Error.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "rtamp/exec/episode_log.hpp"
#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/episode_metrics.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/exec/timeline.hpp"
#include "rtamp/exec/tree_dump.hpp"
#include "rtamp/plan/search.hpp"
#include "rtamp/world/person.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

enum class WorldKind { MuJoCo, Symbolic };
const NameTable<WorldKind>& worlds();  // mujoco symbolic
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
  // One extra random intervention of this kind (world::RandomChange: a
  // relocated or removed subject is an object), at a uniform random time in
  // change_window (seeded; world/person.hpp draws it).
  std::optional<world::Intervention::Kind> random_change;
  double change_window_begin = 2, change_window_end = 20;
  double random_rate = 0;           // random interventions per second (world::PersonOptions' six kinds)
  double failure_probability = 0;   // symbolic world: chance that a move fails
  int max_failures_per_move = 5;
  double outside_grace = 3;
  std::string log_path;    // JSON Lines episode log; empty: none
  std::string tree_dir;    // BehaviorTree.CPP XML of the tree after each change; empty: none
  std::string video_path;  // MP4 of the run (MuJoCo only); empty: none
  std::function<void(const std::string&)> timeline;  // readable lines as they happen; null: quiet
  const std::atomic<int>* interrupt = nullptr;       // nonzero: stop (EndReason::Interrupted)
};

using exec::EpisodeMetrics;

EpisodeMetrics run_episode(const world::Scenario& scenario, const EpisodeOptions& options);

class SimWorld;
class VideoRecorder;

// An episode built and not yet run: its world, loop and observers, for callers
// that drive the loop themselves (`rtamp serve` steps it on its own thread,
// paced to wall time). run_episode(s, o) is Episode(s, o).run().
class Episode {
 public:
  // Wraps the world the loop will see (e.g. to pace it); returns the world to use.
  using WorldWrapper = std::function<std::unique_ptr<exec::World>(exec::World& inner)>;

  Episode(const world::Scenario& scenario, const EpisodeOptions& options, const WorldWrapper& wrap = {});
  ~Episode();
  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;

  // Runs the loop to its end (the caller may have stepped it already) and closes the video.
  EpisodeMetrics run();

  exec::ReactiveLoop& loop() { return *loop_; }
  // The scenario the episode runs (randomized if asked), its script included.
  const world::Scenario& scenario() const { return scenario_; }
  exec::World& world() { return *world_; }  // the world itself (not the wrappers)
  world::Person& person() { return *person_; }
  SimWorld* sim_world() { return sim_world_; }
  exec::SymbolicWorld* symbolic_world() { return symbolic_world_; }
  // The log (null without log_path) — EpisodeLog::add_sink streams it.
  exec::EpisodeLog* log() { return log_.get(); }

 private:
  world::Scenario scenario_;
  std::unique_ptr<exec::EpisodeLog> log_;
  std::unique_ptr<exec::TreeDump> trees_;
  std::unique_ptr<exec::Timeline> timeline_;
  std::unique_ptr<world::Person> person_;
  std::unique_ptr<exec::World> world_;
  std::unique_ptr<exec::PersonWorld> acted_;  // world_ with the person acting on it
  std::unique_ptr<exec::World> wrapper_;
  SimWorld* sim_world_ = nullptr;
  exec::SymbolicWorld* symbolic_world_ = nullptr;
  std::unique_ptr<VideoRecorder> video_;
  std::unique_ptr<exec::ReactiveLoop> loop_;
};

}  // namespace rtamp::episode
