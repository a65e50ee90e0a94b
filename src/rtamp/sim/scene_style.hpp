// How the generated MuJoCo model (mjcf_builder.hpp) looks, for anything that
// draws the same scene (the page of `rtamp serve`): the colour of things of a
// class — a stable palette by name, "block" red, "tray" wood — and of the i-th
// region's outline, and the extent of the table top (its top face at z = 0:
// everything of the scenario on it, the robot's base included, plus 0.15 m).
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

std::array<double, 3> class_colour(const std::string& cls);  // RGB in [0, 1]
std::array<double, 3> region_colour(std::size_t i);

struct TableTop {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
};
TableTop table_top(const world::Scenario& s);

}  // namespace rtamp::sim
