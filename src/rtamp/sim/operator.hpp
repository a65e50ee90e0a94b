// How a person's intervention (paper Section IV-A "unexpected human intervention",
// Section V's operator who relocates, adds and removes blocks and hands over a tray)
// is carried out in the MuJoCo scene: the physics of applying one. Who intervenes
// and when — a script, random interventions — is world::Person's (world/person.hpp),
// which drives the simulation through episode::SimWorld's intervention capability
// or sim::Session.
//
// Semantics of each kind (world::Intervention):
//  - Relocate: move `subject` to `position`, else to a free spot of `location`, else
//    (no location given) of the first other location with room by the rule book.
//    Moving a container carries its contents.
//  - Add / AddContainer: a reserved spare body gets the name and appears at `position`
//    or a free spot of `location` (the first location with room when none is given).
//  - Remove / RemoveContainer: the thing is hidden; a removed tray's contents drop to
//    the table where it stood — or, for a tray in the gripper, are set down in free
//    spots of the region under it, else of the nearest region with room (removed too
//    when there is none; the event's detail says where each went).
//  - TakeFromGripper: the weld is released and the held thing goes to a free spot of
//    `location` (a tray with its contents, keeping its yaw), or is removed when no
//    location is given (a tray's contents are then set down as for a remove).
// Invariants: an intervention never puts a thing where the rule book
// (world/space_rules.hpp: nesting, fit, capacity, room) refuses it — the location named,
// or where an explicit position falls — and is then refused with the symbolic world's
// words (sim::space_refusal). It never puts two things in the same spot: targets come
// from sim::free_spot with the arm's clearance (world::kPlaceGap) over the footprints of
// every present thing (the subject and its contents excluded), and an explicit
// `position` that overlaps something is refused. Every event is reported, applied or not.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::sim {

struct OperatorEvent {
  double time = 0;  // sim time it was applied
  world::Intervention what;
  bool applied = false;
  std::string detail;  // where it went, or why it was refused
};

class Operator {
 public:
  explicit Operator(Simulation& sim);

  // Applies one intervention now (between physics steps).
  OperatorEvent apply(const world::Intervention& iv);
  const std::vector<OperatorEvent>& history() const { return history_; }

 private:
  std::optional<world::Vec3> spot_in(const std::string& location, const world::Body& body,
                                     const std::vector<int>& exclude);
  // Sets down things that were in the air (a removed tray's contents) near `where`;
  // returns the detail to append to the event ("; 'o1' set down in r1 at (...)").
  std::string set_down(const std::vector<int>& things, const Eigen::Vector3d& where);
  bool overlaps_anything(const world::Vec3& base, const world::Vec3& size, const std::vector<int>& exclude) const;
  std::vector<int> contents_of(int container) const;
  world::Geometry current_geometry() const;
  // The first location other than `avoid` (regions, then present containers) that the
  // rule book lets take the thing; else the first of them (its refusal then says why); else "".
  std::string first_location(const std::string& thing, const world::Body& body, const std::vector<int>& exclude,
                             const std::string& avoid);

  Simulation& sim_;
  std::vector<OperatorEvent> history_;
};

}  // namespace rtamp::sim
