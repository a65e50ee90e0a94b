// The fixed part of `hello` (docs/serve.md): the mode and world, the scene a
// page draws (table top, regions, every thing present at the start with its
// class colour, the class palette for "add", the robot's base, yaw, DH table,
// tool offset and home configuration — the same kinematics robot/ and the
// MuJoCo model use), the task and its Büchi automaton (states, initial,
// accepting; edges with their guards as text; an edge is accepting in a
// transition-based automaton when it carries every acceptance mark).
#pragma once

#include <optional>
#include <string>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

// A JSON object's text: {"mode":..,"world":..,"scene":..,"task":..,"automaton":..[,"replay":{"duration":..}]}.
std::string hello_fields(const world::Scenario& scenario, const automata::Automaton& ba, const std::string& mode,
                         const std::string& world_name, std::optional<double> replay_duration = std::nullopt);

// "#rrggbb" of a class (sim::class_colour).
std::string class_colour_hex(const world::Scenario& s, const std::string& cls);

}  // namespace rtamp::serve
