// The command-line options of one episode of the reactive loop, shared by
// `rtamp run` and `rtamp serve` (both run episode::Episode): registered once,
// with one help text, and turned into episode::EpisodeOptions one way.
//
// Invariant: every value is checked by CLI11 while the command line is parsed
// (choices, ranges); to_episode_options() only maps names to enums and never
// fails. Outputs (--log, --trees) are checked by the command before it runs.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "rtamp/episode/episode.hpp"

namespace rtamp::cli {

struct EpisodeArgs {
  std::string scenario, algo = "astar-exp", bt = "online-action", cost = "euclid", log, trees, change,
                        world = "mujoco", planning;
  std::uint64_t seed = 1;
  double max_time = 900, rate = 0, failures = 0;
  int cycles = 0;
  bool random_initial = false, no_operator = false;
};

// SCENARIO, --world, --algo, --bt, --cost, --planning, --seed, --change,
// --rate, --failures, --cycles, --random-initial, --no-operator, --max-time,
// --log (described by `log_help`), --trees.
void add_episode_options(CLI::App& app, EpisodeArgs& args, const std::string& log_help);

// The episode's options (no timeline, no interrupt flag: the command sets those).
episode::EpisodeOptions to_episode_options(const EpisodeArgs& args);

}  // namespace rtamp::cli
