// The one check of an episode log (JSON Lines, docs/exec.md "The episode log"),
// which every reader of a log passes it through before using it: `rtamp serve
// --replay` (docs/serve.md "Replay") and `rtamp log to-mcap`: each line read
// within bounded limits, each record held to the documented record schema.
//
// Limits (docs/formats.md "Episode logs"): a line is at most kMaxLineBytes and
// nests at most kMaxDepth arrays/objects — measured by a scan before parsing,
// so no line can exhaust the stack or the memory of the parser.
// Schema: every record an object with a known "ev" and a time "t" in
// [0, kMaxTime], in time order; exactly one `episode` record, the first, of a
// format version this rtamp reads (kLogVersion; none: 1); exactly one `end`
// record, the last; each kind's documented fields of their documented types;
// every thing a record names exists by then (the scenario's, one an applied
// `intervention` added, or one perception reported in `perceived` / `things`);
// every location a region, a thing, "hand" or "none"; a frame's `q` six angles.
// Names are checked against a scenario: the one given, else the built-in one
// the `episode` record names; a log of another scenario, given none, has its
// names unchecked. A check throws rtamp::Error with why (the caller adds file
// and line); read_episode_log does it all for a file, "PATH:LINE: why".
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "rtamp/exec/episode_log.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

inline constexpr std::size_t kMaxLineBytes = 8u << 20;  // 8 MiB
inline constexpr int kMaxDepth = 16;
inline constexpr double kMaxTime = 1e8;  // world seconds: ten times the largest --max-time
inline constexpr int kLogVersion = exec::kEpisodeLogVersion;  // the `episode` record's "version" it reads

// One line as JSON: rtamp::Error("a line of N bytes (the limit is 8 MiB)",
// "nested deeper than 16 levels", "not a JSON object ...") otherwise.
nlohmann::json parse_log_line(std::string_view line);

class LogCheck {
 public:
  // `scenario` may be null (then the built-in one the log names, if any).
  explicit LogCheck(const world::Scenario* scenario);

  // The next record of the log (throws rtamp::Error on one that breaks the schema).
  void record(const nlohmann::json& j);
  // After the last record: throws if the log had no `end` (or no record).
  void finish() const;

 private:
  void thing(const nlohmann::json& name, const char* field) const;
  void location(const nlohmann::json& name, const char* field) const;
  void placement(const nlohmann::json& j, const char* field, bool introduces);

  void use(const world::Scenario& scenario);

  const world::Scenario* scenario_ = nullptr;
  std::optional<world::Scenario> builtin_;  // the one the log names, when none was given
  std::set<std::string> things_;  // every thing that exists by now
  std::size_t records_ = 0;
  double t_ = 0;
  bool ended_ = false;
};

// Reads and checks the whole log at `path` (LineReader with kMaxLineBytes;
// blank lines skipped), handing each record and its line number to `each`
// (may be null) with its text after it passed the check. Throws rtamp::Error "PATH:LINE: why"
// (a missing file, a directory, a long line, a broken record; "PATH: the log is
// empty" / "no `end` record" after the last line).
void read_episode_log(const std::string& path, const world::Scenario* scenario,
                      const std::function<void(const nlohmann::json& record, const std::string& text, int line)>& each = {});

}  // namespace rtamp::episode
