// The names of a `sim --do` action list (session.hpp: parse_actions) checked
// against the scenario before anything runs, with the rules of every other
// entry point (world/names.hpp): each THING is an object or container of the
// scenario, each LOCATION a region or container, a container goes only into a
// region and nothing into itself. Names the scenario's operator script adds
// count when the script runs (`with_script`). So `move o1 r9` is refused
// before o1 is picked up, never half done.
//
// Errors are rtamp::Error at "--do:1:COLUMN" of the offending word (columns
// of the list text, as parse_actions reports them), with the list and a caret
// as detail and a did-you-mean where one fits. The C++ API (Session::run and
// execute) checks with the vocabulary of the running simulation (the
// scenario's names and those added since) and names its own `source`.
#pragma once

#include <string_view>
#include <vector>

#include "rtamp/sim/session.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

void check_actions(const std::vector<SimAction>& actions, const world::Scenario& scenario, std::string_view text,
                   bool with_script = false);
void check_actions(const std::vector<SimAction>& actions, const world::Vocabulary& vocabulary, std::string_view text,
                   const std::string& source = "--do");

}  // namespace rtamp::sim
