// The table top every world stands on: its top face at z = 0, spanning
// everything of the scenario (regions, containers, objects, the robot's base
// ± 0.25 m) plus a 0.15 m margin. MuJoCo's model (sim/mjcf_builder), the page
// of `rtamp serve` and the rules for where a person may put a thing
// (intervention_rules.hpp, the worlds) use this one extent: a position off it
// is refused everywhere, since a thing put there would fall to the floor.
#pragma once

#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

struct TableTop {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  bool contains(double x, double y) const { return x >= xmin && x <= xmax && y >= ymin && y <= ymax; }
};

TableTop table_top(const Scenario& s);

// "" if (x, y) lies on the table top and z is neither below it (1 mm of
// tolerance) nor more than kMaxPutHeight above it (a person puts a thing down
// on the table or on a tray's floor; they do not drop it from a height), else
// "position [x, y, z] is off the table (x in [..], y in [..])", "... is below
// the table top (z = 0)" or "... is z m above the table top (...)".
inline constexpr double kUnderTableTolerance = 0.001;  // m
inline constexpr double kMaxPutHeight = 0.05;          // m: above a 3 cm tray's rim
std::string off_table(const TableTop& top, const Vec3& p);

}  // namespace rtamp::world
