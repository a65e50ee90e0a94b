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
// the batch goes on — except for a lost output (rtamp::OutputError: a log or
// MCAP file that could not be written), which stops the batch and is rethrown.
// The episodes' interrupt flag (episode.loop.interrupt, set by a signal) stops
// it too: no trial starts after it is set, the running episodes end
// (interrupted, with complete logs and MCAP files) and are not reported —
// they did not run to their end; their records in the result have an empty
// scenario.
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

// The options every episode of the batch starts from (episode::EpisodeOptions,
// the one description of an episode): objects placed at random, no scripted
// operator, planning as the world plans by default.
episode::EpisodeOptions batch_episode_defaults(const std::string& world = "mujoco");

struct BatchOptions {
  int jobs = 2;          // worker threads (>= 1)
  std::string log_dir;   // JSON Lines log per episode into this directory; empty: none
  bool mcap = false;     // and an MCAP file beside each log (the same name, .mcap)
  // Every episode's options; each trial sets its algorithm, tree form, seed,
  // log file and random change (of the trial's kind, in the window of
  // episode.person.change if set, else world::RandomChange's 2-20 s).
  episode::EpisodeOptions episode = batch_episode_defaults();
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
