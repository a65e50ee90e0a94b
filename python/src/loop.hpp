// The reactive loop for Python (loop.cpp): the World trampoline (a world
// written in Python: the way a user plugs in their robot and perception) and
// the conversion of Python placements. worlds.cpp binds the C++ worlds on the
// same World base.
#pragma once

#include <map>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::python {

// name -> (class, container), from a scenario.
using ClassTable = std::map<std::string, std::pair<std::string, bool>>;
ClassTable class_table(const world::Scenario& s);

// A Placement from a Placement or a {thing: location | (location, cls[, container]) | Thing}
// dict; plain locations take their class from `classes` (else "block", not a container).
world::Placement to_placement(const py::handle& o, const ClassTable& classes);

}  // namespace rtamp::python
