// validate(): the invariants of a Scenario (scenario.hpp), checked for
// scenarios loaded from YAML (scenario_io.hpp calls it) and for scenarios built
// in code (generator.hpp, tests, other layers). Throws the first violation as
// rtamp::Error at the offending element's source location.
//
// Checked: a name; a robot model rtamp knows (ur5); at least one region;
// names are identifiers [A-Za-z_][A-Za-z0-9_]* (at most 64 characters, not a
// keyword of the proposition grammar, not "none"), unique across regions,
// containers, objects and things added by interventions; classes are
// identifiers other than "object", and no class names both objects and
// containers; coordinates are finite and within ±1000 m; the robot's yaw
// within ±2π; regions lie on the table top (centre z = 0, table.hpp) and
// things start resting on their location's surface (at most 2 cm above it,
// geometry.hpp); a scripted position is on the table (table.hpp); sizes are positive
// (regions: x and y) and at most 100 m; capacities are >= 1; regions do not
// overlap; containers do not overlap each other and each stands in a region;
// every object lies in a container or a region (geometry.hpp); every thing's
// footprint fits the location it starts in (fit.hpp: x and y sizes within the
// region's size or the container's floor inside its rims; no rotation); no location
// initially holds more things than its capacity (a region counts the objects
// directly in it and the containers standing in it); proposition names are
// [a-z_][A-Za-z0-9_]* and not true/false, and every name their expressions
// use exists (things and containers present at the start or added by an
// intervention; classes of such things, or "object"); the task is not blank;
// interventions are sorted by time, times are finite and >= 0, and each names
// things that exist at its time, a target location that exists then (a
// container only for objects), and a position inside its target region;
// cameras (camera.hpp) have unique identifier names, a resolution of 16 to 4096
// pixels a side, a field of view in (0°, 180°), a range 0 < near < far <= 100 m,
// a rate in (0, 1000] Hz, noise within bounds; a fixed camera stands above the
// table top (z > 0), does not look at itself and sees some region's centre; a
// wrist camera sits within 0.5 m of the flange.
#pragma once

#include <functional>
#include <string_view>

#include "rtamp/world/names.hpp"  // the name rules (is_valid_name, ...)
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

void validate(const Scenario& s);

inline constexpr double kMaxCoordinate = 1000.0;  // m
inline constexpr double kMaxSize = 100.0;         // m
inline constexpr double kMaxYaw = 6.283185307179586;  // rad: 2π

namespace detail {
// Maps (an element's `where`, a field name such as "size") to the field's own
// location; the YAML loader passes one so errors point at the exact field.
using FieldLocator = std::function<SourceLocation(const SourceLocation& element, std::string_view field)>;
void validate(const Scenario& s, const FieldLocator& locate_field);
}  // namespace detail

}  // namespace rtamp::world
