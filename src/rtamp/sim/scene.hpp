// Questions about the current scene that perception, the operator and the skill runner
// share: the symbolic geometry with the containers where they are NOW, which things a
// container holds, whether a location may take a thing now (the rule book,
// world/space_rules.hpp, on the scene's counts), and free spots that overlap nothing (a
// search over the location, nearest its centre or, for objects in a region, nearest
// its corner by the robot, against the footprints of every present thing).
// Invariant: a spot returned by free_spot() keeps `gap` from every present thing's
// footprint except the excluded ones and the target container itself.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rtamp/robot/skills.hpp"
#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::sim {

// Regions of the scenario and every present, not-held container at its current pose.
world::Geometry current_geometry(const Simulation& sim);

// Centre of a thing's base (a block's body origin is its centre, a tray's its base).
Eigen::Vector3d base_point(const Simulation& sim, int thing);
// Base point and yaw about world z.
robot::ThingPose thing_pose(const Simulation& sim, int thing);

// Location of a present thing by the geometric abstraction ("hand" is not considered).
std::string location_of(const Simulation& sim, const world::Geometry& g, int thing);

// Present objects (not containers, not held) whose base lies in `container` (also while
// the container itself is in the gripper: what rides on it).
std::vector<int> contents_of(const Simulation& sim, int container);

// The capacity of a present container: its scenario entry's, else that of the scenario's
// first container of its class, else 4 (as the symbolic world and the loop count an
// added container).
int container_capacity(const Simulation& sim, int container);

// The rule book's answer (world::refusal: location kind, nesting, fit, capacity, room)
// for putting `thing` (of `body`) into `location` now: "" if it may go there, else why
// not, in the symbolic world's words. Things are counted where perception would locate
// them; the held thing and `exclude` (the thing itself, what rides on it) do not count.
std::string space_refusal(const Simulation& sim, const std::string& thing, const world::Body& body,
                          const std::string& location, const std::vector<int>& exclude);

// A free spot (centre of the base) for a thing of `body` in `location`: inside its
// footprint, keeping `gap` from every present thing (except `exclude`; from a container
// standing there at most world::kContainerGap) and not overlapping `keep_clear` (or a
// target tray's rims); of all such spots on a 5 mm grid and those touching an occupied
// footprint's edge, the one nearest the anchor: for an object put into a region, the
// region's corner nearest the robot's base (so things of one size fill the grid of
// world/fit.hpp's room rule, leaving the middle to trays); for a container, or
// anything put into a container, the area's centre. nullopt if the location is unknown
// or full.
std::optional<world::Vec3> free_spot(const Simulation& sim, const std::string& location, const world::Body& body,
                                     const std::vector<int>& exclude, double gap = world::kPlaceGap,
                                     const std::vector<world::Footprint>& keep_clear = {});

}  // namespace rtamp::sim
