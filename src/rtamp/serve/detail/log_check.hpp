// The check an episode log (JSON Lines, docs/exec.md "The episode log") passes
// before `rtamp serve --replay` serves it (docs/serve.md "Replay"): each line
// read within bounded limits, each record held to the documented record schema.
//
// Limits (docs/formats.md "Episode logs"): a line is at most kMaxLineBytes and
// nests at most kMaxDepth arrays/objects — measured by a scan before parsing,
// so no line can exhaust the stack or the memory of the parser.
// Schema: every record an object with a known "ev" and a finite "t" >= 0, in
// time order; exactly one `episode` record, the first; exactly one `end`
// record, the last; each kind's documented fields of their documented types;
// every thing a record names exists by then (the scenario's, one an applied
// `intervention` added, or one perception reported in `perceived` / `things`);
// every location a region, a thing, "hand" or "none"; a frame's `q` six angles.
// A check throws rtamp::Error with why (the caller adds file and line).
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

inline constexpr std::size_t kMaxLineBytes = 8u << 20;  // 8 MiB
inline constexpr int kMaxDepth = 16;

// One line as JSON: rtamp::Error("a line of N bytes (the limit is 8 MiB)",
// "nested deeper than 16 levels", "not a JSON object ...") otherwise.
nlohmann::json parse_log_line(std::string_view line);

class LogCheck {
 public:
  explicit LogCheck(const world::Scenario& scenario);

  // The next record of the log (throws rtamp::Error on one that breaks the schema).
  void record(const nlohmann::json& j);
  // After the last record: throws if the log had no `end` (or no record).
  void finish() const;

 private:
  void thing(const nlohmann::json& name, const char* field) const;
  void location(const nlohmann::json& name, const char* field) const;
  void placement(const nlohmann::json& j, const char* field, bool introduces);

  const world::Scenario& scenario_;
  std::set<std::string> things_;  // every thing that exists by now
  std::size_t records_ = 0;
  double t_ = 0;
  bool ended_ = false;
};

}  // namespace rtamp::serve
