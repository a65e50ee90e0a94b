// Scenario generator (`rtamp gen`): parametric scenes for the planning
// benchmarks — the paper's Section V partial-graph experiment uses five
// regions at random locations and two to six objects. Deterministic: the same
// options (and seed) give the same scenario on every machine (our own
// mt19937_64-based sampling, not std:: distributions, whose output differs
// between standard libraries).
//
// The scene: regions r1..rM, all the same square size, big enough for every
// object on a grid of pitch 6 cm (4 cm blocks, 2 cm apart), at least 26 cm,
// and with room by the rule book (world/space_rules.hpp, the planner's) for
// all N blocks, and by the area bound (world/fit.hpp) for the N blocks and one
// tray at once (the rule book's shares of a mixed set are an estimate, and
// taking them would grow the regions past what a random layout can place);
// each with capacity N + C. Objects
// o1..oN (class block, 4 cm cubes) start on that grid in r1. Containers
// t1..tC (class tray, 24 x 16 x 3 cm, capacity 4) stand one per region in
// rM, rM-1, ..., r2 (so C <= M - 1). Propositions: all_in_r2 = "all block in
// r2" (when M >= 2) plus the user's; task: F G all_in_r2 unless given.
//  - layout line: centres on the line x = 0.5, y spaced 0.5 m apart (more if
//    the regions are wider than 0.45 m), centred on y = 0.
//  - layout random: centres uniform in the square x in [0.2, 1.2],
//    y in [-0.5, 0.5]; a centre whose region would overlap an earlier one (or
//    come within 2 cm of it) is resampled, up to 10000 tries per region.
// Generated scenes are for planning: they need not be reachable by the arm.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

struct GeneratorOptions {
  enum class Layout { Line, Random };
  int regions = 2;     // M, 1..64
  int objects = 3;     // N, 1..256
  int containers = 0;  // C, 0..M-1
  Layout layout = Layout::Line;
  std::uint64_t seed = 1;
  std::string task;  // empty: "F G all_in_r2"
  SourceLocation task_where;  // optional: where the task's text comes from (e.g. {"--task", 1, 1})
  // Extra propositions (name, expression), added after all_in_r2.
  std::vector<std::pair<std::string, std::string>> propositions;
  // Optional, one per extra proposition: where its expression's text starts
  // (e.g. {"--prop #2", 1, 6}), so that errors point into it.
  std::vector<SourceLocation> proposition_where;
};

// Throws rtamp::Error for options out of range or a random layout that cannot
// be placed. The result passes validate().
Scenario generate_scenario(const GeneratorOptions& options);

// "line" / "random"; throws rtamp::Error for anything else.
GeneratorOptions::Layout parse_layout(const std::string& name);

}  // namespace rtamp::world
