// rtamp log to-mcap — convert an episode's JSON Lines log (from `rtamp run|serve
// --log`, `rtamp batch --log-dir`) to MCAP for Foxglove and other MCAP viewers
// (episode/episode_mcap.hpp). The scene's regions come from --scenario, else
// from the built-in scenario the log's `episode` record names. The log is
// checked whole first, with the check of `serve --replay` (episode/log_check.hpp):
// a log that breaks it is "LOG:LINE: what", exit 2, and OUT is not touched.
// OUT is written as every output is (util/output_file.hpp); one that is LOG is refused.
#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "options.hpp"
#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/util/text_file.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

struct ToMcapArgs {
  std::string log, out, scenario;
  rtamp::episode::McapCompression compression = rtamp::episode::McapCompression::Zstd;
  rtamp::episode::McapProfile profile = rtamp::episode::McapProfile::Json;
  int chunk_kib = 1024;
};

int run_to_mcap(const ToMcapArgs& a) {
  {  // OUT may not be LOG (nor the scenario): checked by device and inode before anything is read
    rtamp::FileSet files;
    files.input("LOG", a.log);
    if (!a.scenario.empty() && rtamp::path_exists(a.scenario)) files.input("--scenario", a.scenario);
    files.output("OUT", a.out);
  }
  rtamp::cli::check_output_file("OUT", a.out);
  std::optional<rtamp::world::Scenario> scenario;
  if (!a.scenario.empty()) scenario = rtamp::world::load_scenario(a.scenario);
  const std::uint64_t n = rtamp::episode::log_to_mcap(a.log, a.out, a.compression, scenario ? &*scenario : nullptr,
                                                         static_cast<std::size_t>(a.chunk_kib) * 1024, a.profile);
  std::cerr << a.out << ": " << n << " records\n";
  return 0;
}

rtamp::cli::Registrar reg{
    "log", "Episode logs: convert a JSON Lines log to MCAP",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto args = std::make_shared<ToMcapArgs>();
      sub.require_subcommand(1);
      CLI::App* to = sub.add_subcommand(
          "to-mcap",
          "Write the episode log LOG as the MCAP file OUT: every record on /rtamp/log, and the scene, arm, plan, "
          "tree, automaton, interventions, replans and timeline on channels with Foxglove JSON schemas "
          "(docs/formats.md \"MCAP\")");
      to->add_option("log", args->log, "The JSON Lines episode log")->required();
      to->add_option("out", args->out, "The MCAP file to write")->required();
      rtamp::cli::add_choice_with(
          *to, "--compression", rtamp::cli::mcap_compression_choices(), "zstd",
          [args](const std::string& s) { args->compression = rtamp::episode::parse_mcap_compression(s); },
          "Compression of the chunks:");
      rtamp::cli::add_choice_with(
          *to, "--mcap-profile", rtamp::cli::mcap_profile_choices(), "json",
          [args](const std::string& s) { args->profile = rtamp::episode::parse_mcap_profile(s); },
          "Profile of OUT (docs/formats.md):");
      rtamp::cli::add_integer(*to, "--chunk-kib", args->chunk_kib, 1, 1 << 20,
                              "Close a chunk when its uncompressed records reach this many KiB (default 1024)");
      to->add_option("--scenario", args->scenario,
                     "The episode's scenario (YAML file or built-in name) for the regions and initial spots "
                     "(default: the built-in the log names, if any)");
      return [args]() { return run_to_mcap(*args); };
    }};

}  // namespace
