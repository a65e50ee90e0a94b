// The command-line options of one episode of the reactive loop, shared by
// `rtamp run` and `rtamp serve` (both run episode::Episode): registered once,
// with one help text, each stored straight into episode::EpisodeOptions.
//
// Invariant: every value is checked by CLI11 while the command line is parsed
// (choices from the library's tables and registries, ranges); only the
// planning mode's default is settled after parsing (the world's). Outputs
// (--log, --mcap, --trees) are checked by the command before it runs.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "options.hpp"
#include "rtamp/episode/episode.hpp"

namespace rtamp::cli {

struct EpisodeArgs {
  std::string scenario;
  episode::EpisodeOptions episode;
  CLI::Option* planning = nullptr;
};

// SCENARIO, --world, --algo, --bt, --cost, --planning, --seed, --change,
// --rate, --failures, --cycles, --new-task, --random-initial, --no-operator, --max-time,
// --log (described by `log_help`), --mcap, --mcap-compression, --mcap-image-period, --trees.
void add_episode_options(CLI::App& app, EpisodeArgs& args, const std::string& log_help);
// --mcap-image-period S (>= 0 or inf), into `target` (also `rtamp batch`'s).
CLI::Option* add_mcap_image_period(CLI::App& app, double& target);
// --perception-cameras NAME,NAME,... into `target`.
CLI::Option* add_perception_cameras(CLI::App& app, std::vector<std::string>& target);

// The episode's options after parsing: without --planning, the world's
// planning mode (world_registry.hpp). No timeline, no interrupt flag: the command sets those.
episode::EpisodeOptions episode_options(const EpisodeArgs& args);

// The registered worlds as choices.
std::vector<Choice> world_choices();
// truth / camera, for --perception.
std::vector<Choice> perception_choices();

}  // namespace rtamp::cli
