// Reading and writing scenarios as YAML (docs/design.md "Files users touch"; the
// format is documented with a complete example in docs/scenario.md).
//
// parse_scenario() is strict: unknown keys (typos), wrong types, missing
// required fields, malformed proposition expressions and every invariant of
// validate.hpp are rtamp::Error with file:line:column of the offending YAML
// node and what is wrong. It never crashes or hangs on any input (the fuzz
// target fuzz/fuzz_scenario_yaml.cpp checks this); inputs over 16 MiB are refused.
//
// Round trip: for every scenario s that parse_scenario() returns,
// parse_scenario(to_yaml(s)) is equivalent to s (compare.hpp).
//
// The LTL task is kept as text: the ltl layer parses it (the world layer does
// not depend on ltl), so atoms of the task that are not propositions are
// reported by the layer that parses the task.
#pragma once

#include <string>
#include <string_view>

#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

// `path_or_builtin`: the name of a built-in scenario (builtin_scenarios.hpp,
// e.g. "3-block") or the path of a YAML file. A built-in name wins; write
// ./3-block to read a file of that name instead.
Scenario load_scenario(const std::string& path_or_builtin);

// Parses and validates YAML text; `source_name` is used in error locations and
// stored in Scenario::source.
Scenario parse_scenario(std::string_view yaml_text, const std::string& source_name);

// The scenario as YAML in the documented format (flow style for each region,
// container, object and operator action; numbers printed in the shortest form
// that reads back exactly).
std::string to_yaml(const Scenario& s);

inline constexpr std::size_t kMaxScenarioBytes = 16u << 20;

}  // namespace rtamp::world
