// The colour of every class of a scene by default — how things are drawn (MuJoCo, the
// page) and, with camera perception, told apart (the paper's identity by colour:
// colour_segmentation.hpp). In this order of precedence:
//  1. a class the scenario's `colours:` lists has that colour (collisions among the
//     user's own are theirs: check_scene_colours refuses them);
//  2. a class named after a colour — its name, or a word of it ("red", "blue_cube",
//     "bigGreen") in a small table of common colour names — gets that colour, in
//     declaration order: the table's, or a hue at most 10° from it where that keeps it
//     apart from the colours before it and from the regions' and the arm's hues;
//  3. `block` red and `tray` wood;
//  4. every other class, in declaration order, the hue farthest from every colour
//     assigned before it (preferring hues away from the regions' and the arm's too).
// A default of steps 2 and 3 within kMinHueApart of a colour assigned before it takes a
// free hue by step 4 instead. So default colours never collide with each other or with
// a user's: every pair of thing classes is at least kMinHueApart apart in hue (the
// segmentation's measure, hue_angle_deg) while the hue circle has room (some 20 classes).
// Declaration order: the first thing, container or operator action of the scenario
// that names the class, by its place in the file (objects, containers, operator actions
// for a scenario built in code); a class the scenario does not name at all comes last.
#pragma once

#include <array>
#include <map>
#include <string>

#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

// Twice the colour segmentation's default acceptance angle (ColourSegmentationOptions).
inline constexpr double kMinHueApart = 12.0;  // degrees

using Rgb = std::array<double, 3>;  // each channel in [0, 1]

// The colour of a colour name of the table ("red", "teal", ...; lower case), if it has one.
const Rgb* named_colour(const std::string& name);
// The colour table's entry a class name is named after (its name or its first word that
// is a colour name, case-insensitive), if any.
const Rgb* colour_named_in(const std::string& cls);

// Every class of `s` (its things, containers and operator actions, `block` and `tray`)
// and, if not among them, `extra`, with its colour by the rules above.
std::map<std::string, Rgb> class_colours(const world::Scenario& s, const std::string& extra = {});

}  // namespace rtamp::sim
