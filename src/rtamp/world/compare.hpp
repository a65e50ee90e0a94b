// Content equality of scenarios: equal in everything a scenario says about the
// world, ignoring where things were written (SourceLocation members) and the
// file it came from (Scenario::source). Doubles compare exactly: the YAML
// writer prints the shortest text that reads back to the same double, so
// parse_scenario(to_yaml(s)) is equivalent to s (the round-trip property the
// tests and the fuzz target check).
#pragma once

#include <string>

#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

bool equivalent(const Scenario& a, const Scenario& b);

// A description of the first difference ("objects[2].position: [0.4, 0.3, 0] vs [0.4, 0.31, 0]"), or "" if equivalent.
std::string first_difference(const Scenario& a, const Scenario& b);

}  // namespace rtamp::world
