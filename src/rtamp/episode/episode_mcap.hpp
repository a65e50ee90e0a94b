// An episode's log as an MCAP file that Foxglove and other MCAP viewers draw
// without plugins: every JSON Lines record of the episode log (exec/episode_log.hpp)
// goes in, as it is, on /rtamp/log — so that channel holds exactly the log's
// records — and is turned into messages of JSON channels with JSON Schemas in
// the Foxglove conventions (docs/formats.md "MCAP"):
//   /scene          foxglove.SceneUpdate   regions, trays and blocks (from `frame`
//                                          records, else laid out from `perceived`
//                                          and `end` placements: exec/thing_layout.hpp)
//   /joint_states   foxglove.JointStates   the UR5's joint angles (`frame` records with q, or arm())
//   /tf             foxglove.FrameTransforms  the arm's link frames, a chain from the world (UR5 FK)
//   /plan           rtamp.Plan             each plan
//   /tree           rtamp.TreeStatus       tree changes and the tick status when it changes
//   /task           rtamp.Task             the task in force: at the start and at every task change
//   /automaton      rtamp.Automaton        its Büchi automaton, at the same times
//   /automaton/tracked  rtamp.AutomatonStates  the tracked Büchi states after each step of the run
//   /timeline       foxglove.Log           everything that happened, one line each
//   /interventions  foxglove.Log           interventions (refused ones as warnings)
//   /replans        foxglove.Log           replan requests
// and the channels of observers that write their own (add_channel, write: a
// camera's images, mcap_camera.hpp). Message times are the records' world times (ns).
// The Header's library is "rtamp VERSION"; the `episode` record also gives a Metadata
// record "rtamp" (version, scenario, task, world, seed, algorithm). Used live, as a sink of the
// episode log (Episode, `--mcap`), and by `rtamp log to-mcap` on a finished log.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "rtamp/episode/mcap_profile.hpp"
#include "rtamp/episode/mcap_writer.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

class EpisodeMcap {
 public:
  // Opens `path` (rtamp::Error if it cannot be written). `scenario` (may be
  // null) gives the regions and where things start; without it, the scenario
  // the `episode` record names is used if it is a built-in one.
  EpisodeMcap(const std::string& path, McapCompression compression, const world::Scenario* scenario,
              std::size_t chunk_bytes = 1 << 20, const std::string& what = "--mcap");
  ~EpisodeMcap();

  // One record of the log (one JSON object with "ev" and "t", no newline);
  // rtamp::Error if it is not one.
  void add(std::string_view record);
  // The arm at world time `t` (s), joint angles `q` (rad): /joint_states and
  // /tf, as a `frame` record with q gives them (live MuJoCo episodes: McapArm).
  // Once called, `frame` records' joint angles are not drawn (no arm twice).
  void arm(double t, const std::array<double, 6>& q);
  // A channel of JSON messages whose JSON Schema `schema` is titled
  // `schema_name` (a schema is written once per name), for observers that
  // write messages of their own; its id for write().
  std::uint16_t add_channel(const std::string& topic, const std::string& schema_name, const std::string& schema);
  // One message (JSON text) of such a channel at world time `t` (s).
  void write(std::uint16_t channel, double t, std::string_view message);
  // Writes the summary and closes the file (the destructor does it quietly).
  void close();
  // Closes quietly and removes the file if it is a regular one.
  void discard() noexcept;

  std::uint64_t records() const { return records_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::uint64_t records_ = 0;
};

// Converts the JSON Lines log at `log_path` to `mcap_path` in `profile`
// (log_to_mcap.cpp). The log is checked whole first (log_check.hpp, the check of
// `serve --replay`): rtamp::Error "LOG:LINE: what" for a log that breaks it,
// before the output is opened. A write that fails: rtamp::OutputError, and no
// output left (a regular file is removed). Returns the number of records.
std::uint64_t log_to_mcap(const std::string& log_path, const std::string& mcap_path, McapCompression compression,
                          const world::Scenario* scenario = nullptr, std::size_t chunk_bytes = 1 << 20,
                          McapProfile profile = McapProfile::Json);

}  // namespace rtamp::episode
