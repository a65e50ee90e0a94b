// How the generated MuJoCo model (mjcf_builder.hpp) looks, for anything that
// draws the same scene (the page of `rtamp serve`): the colour of things of a
// class — the scenario's `colours:` where it lists the class, else its default
// (class_colours.hpp: a colour its name names, `block` red, `tray` wood, other classes
// distinct hues in declaration order, never within 12° of hue of another class) — and
// of the i-th region's outline (the table top's extent is world/table.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

std::array<double, 3> class_colour(const world::Scenario& s, const std::string& cls);  // RGB in [0, 1]
std::array<double, 3> region_colour(std::size_t i);


}  // namespace rtamp::sim
