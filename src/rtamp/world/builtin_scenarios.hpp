// The built-in scenarios: the YAML files of the repository's scenarios/
// folder, embedded into the library when it is built (embed_scenarios.cmake),
// so that `rtamp run 3-block` works from an installed binary anywhere.
// A built-in's name is its file name without ".yaml": "3-block" (the paper's
// Section V 3-block task) and "3-block-tray" (3-block + tray).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtamp::world {

// Names of the built-in scenarios, sorted.
std::vector<std::string> builtin_scenario_names();

// The YAML text of a built-in scenario, or nullopt if there is none of that name.
std::optional<std::string_view> builtin_scenario_text(std::string_view name);

}  // namespace rtamp::world
