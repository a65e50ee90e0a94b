// One episode of the reactive loop (exec::ReactiveLoop, the paper's Algorithm
// 1) on a scenario, assembled from parts: a world by name (world_registry.hpp:
// the MuJoCo UR5, the symbolic world, or one the user registered), the person
// who acts on it (world::Person, driving the world through exec::PersonWorld),
// the loop's options, and the outputs — the JSON Lines log, the readable
// timeline, tree dumps and video (worlds that film: MuJoCo). EpisodeOptions is
// the one description of an episode that `rtamp run|serve|batch` and Python
// fill in; programs that bring their own loop use exec::ReactiveLoop directly.
//
// Every input (the task, the world's name and settings, the person's and the
// loop's numbers, the planner's names) is checked before any output file is
// opened, and the outputs before the episode starts: a bad one is an
// rtamp::Error thrown before anything is written or runs; two outputs that
// are one file are refused (util/file_set.hpp). Errors inside the episode end
// it with EndReason::Error and a complete log; a video encoder that failed,
// or an output that was lost (a full disk: util/output_file.hpp), then throws
// its rtamp::Error (rtamp::OutputError) when the episode ends.
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
#include "rtamp/exec/timeline.hpp"
#include "rtamp/exec/tree_dump.hpp"
#include "rtamp/episode/mcap_profile.hpp"
#include "rtamp/episode/mcap_writer.hpp"
#include "rtamp/episode/world_registry.hpp"
#include "rtamp/world/person.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

// Where the episode writes what happens (each empty or null: none).
struct EpisodeOutputs {
  std::string log;    // JSON Lines episode log (docs/exec.md)
  std::string mcap;   // the same records as MCAP, with Foxglove channels (episode_mcap.hpp)
  McapCompression mcap_compression = McapCompression::Zstd;
  // JSON channels (episode_mcap.hpp) or the ROS 2 profile: CDR on ROS 2's topics (mcap_ros2.hpp).
  McapProfile mcap_profile = McapProfile::Json;
  // Camera perception: world seconds between the images written to the MCAP file
  // (mcap_camera.hpp); 0: every frame; inf: none. >= 0 (rtamp::Error otherwise).
  double mcap_image_period = 1;
  std::string trees;  // directory: BehaviorTree.CPP XML of the tree after each change
  std::string video;  // MP4 of the run (worlds that film: MuJoCo)
  // How errors name the log and the MCAP file (the option that gave them).
  std::string log_option = "--log", mcap_option = "--mcap";
  std::function<void(const std::string&)> timeline;  // readable lines as they happen
};

struct EpisodeOptions {
  std::string world = "mujoco";  // a registered world (world_registry.hpp)
  WorldSettings world_settings;
  // One seed for the episode: the world's draws, the person's, the random
  // initial layout; the loop reports it (the sub-options' own seeds are ignored).
  std::uint64_t seed = 1;
  bool randomize_initial = false;  // shuffle objects inside their initial locations (seeded)
  // The person: random interventions (rate, kinds, window), one random change
  // (world::RandomChange), and script entries; the scenario's `operator:`
  // script comes first unless scripted_operator is false.
  world::PersonOptions person;
  bool scripted_operator = true;
  // The loop: the planner (algorithm, cost model), the tree's form, planning
  // mode, limits, new tasks at given times, the interrupt flag. Its
  // world_name is the world's; the scenario's scripted new tasks are put
  // before its task_changes unless scripted_operator is false.
  exec::LoopOptions loop;
  EpisodeOutputs outputs;
};

using exec::EpisodeMetrics;

EpisodeMetrics run_episode(const world::Scenario& scenario, const EpisodeOptions& options);

class EpisodeMcap;
class McapArm;
class McapCamera;
class McapRos2;
class McapRos2Frames;
class McapRos2Camera;
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
  // The MuJoCo world, if the episode runs in one (null otherwise).
  SimWorld* sim_world() { return sim_world_; }
  // The log (null without a log file or an MCAP file) — EpisodeLog::add_sink streams it.
  exec::EpisodeLog* log() { return log_.get(); }

 private:
  world::Scenario scenario_;
  std::unique_ptr<EpisodeMcap> mcap_;  // fed by log_'s sink
  std::unique_ptr<McapRos2> mcap_ros2_;  // the same, in the ros2 profile (--mcap-profile ros2)
  std::unique_ptr<McapRos2Frames> mcap_ros2_frames_;  // the world's frames into mcap_ros2_
  std::vector<std::unique_ptr<McapRos2Camera>> mcap_ros2_cameras_;  // camera images into mcap_ros2_, per camera
  std::unique_ptr<exec::EpisodeLog> log_;
  std::unique_ptr<McapArm> mcap_arm_;  // the MuJoCo arm's joint angles into mcap_
  std::vector<std::unique_ptr<McapCamera>> mcap_cameras_;  // camera perception's images into mcap_, per camera
  std::unique_ptr<exec::TreeDump> trees_;
  std::unique_ptr<exec::Timeline> timeline_;
  std::unique_ptr<world::Person> person_;
  std::unique_ptr<exec::World> world_;
  std::unique_ptr<exec::PersonWorld> acted_;  // world_ with the person acting on it (if it can take them)
  std::unique_ptr<exec::World> wrapper_;
  SimWorld* sim_world_ = nullptr;
  std::unique_ptr<VideoRecorder> video_;
  std::unique_ptr<exec::ReactiveLoop> loop_;
};

}  // namespace rtamp::episode
