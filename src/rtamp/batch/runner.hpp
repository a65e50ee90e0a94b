// Running a batch of episodes (`rtamp batch`): each trial of the grid
// (trials.hpp) is one independent episode of the reactive loop
// (episode::run_episode, the paper's Algorithm 1) with the objects placed at
// random inside their initial locations and one random intervention of the
// trial's change kind at a random time — the protocol of the paper's
// Section VI ("30 test scenarios ... randomly placing objects in the beginning
// and then introduced an additional environmental change").
//
// Episodes run on `jobs` worker threads, each episode with its own world,
// planner and tree (run_episode shares no mutable state between episodes), so
// the results do not depend on `jobs` or on the order episodes finish in,
// except through measured wall times (planning time is charged to simulated
// time, so completion times move a little with machine load).
//
// An episode that throws is recorded as a failure with reason "error: ...";
// the batch goes on.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rtamp/episode/episode.hpp"
#include "rtamp/batch/record.hpp"
#include "rtamp/batch/trials.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::batch {

struct BatchOptions {
  int jobs = 2;                   // worker threads (>= 1)
  double max_time = 900;          // simulated seconds before an episode gives up
  std::string cost = "euclid";    // planner cost model
  bool randomize_initial = true;  // random object placement (seeded)
  bool scripted_operator = false; // also apply the scenario's own `operator:` script
  double change_window_begin = 2, change_window_end = 20;  // s, when the random change happens (within every task)
  std::string log_dir;            // JSON Lines log per episode into this directory; empty: none
  episode::WorldKind world = episode::WorldKind::MuJoCo;  // or the symbolic world (no physics)
};

// The episode options of one trial.
episode::EpisodeOptions episode_options(const Trial& trial, const BatchOptions& options);
// Log file name of a trial inside log_dir: "<change>-<algorithm>-<bt>-<trial>.jsonl".
std::string log_file_name(const Trial& trial);
// The CSV row of a finished episode.
EpisodeRecord make_record(const std::string& scenario, const Trial& trial, const exec::EpisodeMetrics& m);

// Called after each episode, one call at a time (never concurrently).
using EpisodeDone = std::function<void(const Trial&, const EpisodeRecord&)>;

// Runs every trial; the result is index-aligned with `trials`.
std::vector<EpisodeRecord> run_batch(const world::Scenario& scenario, const std::vector<Trial>& trials,
                                     const BatchOptions& options, const EpisodeDone& on_done = {});

}  // namespace rtamp::batch
