// The names Python uses for rtamp's choices are the library's own tables
// (util/names_table.hpp: exec::condition_modes(), exec::planning_modes(),
// episode::worlds(), world::intervention_kinds(), ...), the same the CLI
// reads; parse_name() / name_of() turn them to values and back.
#pragma once

#include <string>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/plan/algorithm.hpp"
#include "rtamp/util/names_table.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::python {

// world::intervention_kinds() by name (rtamp::Error for others) and back.
world::Intervention::Kind parse_intervention_kind(const std::string& s);
const char* intervention_kind_name(world::Intervention::Kind k);

}  // namespace rtamp::python
