// The human operator (paper Section IV-A "unexpected human intervention", Section V's
// operator who relocates, adds and removes blocks and hands over a tray): applies
// world::Intervention's to the simulation at scripted times and, optionally, random
// ones at seeded Poisson times.
//
// Semantics of each kind (world::Intervention):
//  - Relocate: move `subject` to `position`, else to a free spot of `location`, else to
//    a free spot of a random other location with room. Moving a container carries its
//    contents.
//  - Add / AddContainer: a reserved spare body gets the name and appears at `position`
//    or a free spot of `location` (a random region when none is given).
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
#include <random>
#include <string>
#include <vector>

#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::sim {

struct OperatorOptions {
  std::vector<world::Intervention> script;  // applied when sim time reaches .time
  double random_rate = 0;                   // random interventions per second of sim time
  double random_start = 0;                  // no random intervention before this time
  std::vector<world::Intervention::Kind> random_kinds{world::Intervention::Kind::Relocate,
                                                      world::Intervention::Kind::Add,
                                                      world::Intervention::Kind::Remove};
  std::uint64_t seed = 1;
};

struct OperatorEvent {
  double time = 0;  // sim time it was applied
  world::Intervention what;
  bool applied = false;
  std::string detail;  // where it went, or why it was refused
};

class Operator {
 public:
  Operator(Simulation& sim, OperatorOptions options = {});

  // Applies every intervention due by the current sim time; returns them (empty if none).
  std::vector<OperatorEvent> update();
  // Applies one intervention now.
  OperatorEvent apply(const world::Intervention& iv);
  // Time of the next scripted or random intervention (infinity if none).
  double next_time() const;
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
  std::string random_location(const std::string& thing, const world::Body& body, const std::vector<int>& exclude,
                              const std::string& avoid);
  world::Intervention random_intervention();
  void schedule_random();

  Simulation& sim_;
  OperatorOptions options_;
  std::mt19937_64 rng_;
  std::size_t next_script_ = 0;
  double next_random_ = 0;
  int added_ = 0;
  std::vector<OperatorEvent> history_;
};

}  // namespace rtamp::sim
