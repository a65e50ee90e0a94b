// SymbolicWorld: an exec::World (world.hpp) with no physics — an exact
// symbolic placement, a discrete-event model of the arm's moves, seeded
// failures, and the rules of applying a person's intervention (the
// intervention capability, intervenable.hpp; the person who decides what and
// when is world::Person, driving it through exec::PersonWorld). It runs the
// reactive loop (the paper's Algorithm 1) thousands of times a second for
// property tests and is `rtamp run --world symbolic`. docs/symbolic-world.md
// documents the timing model and every intervention's semantics in full.
//
// Invariants (check_invariants() verifies them; no call, intervention or
// failure breaks them):
//  - every present thing is in exactly one place: a region, a present
//    container, kInHand (at most one thing, the running move's, while held) or
//    world::kNoLocation ("none": the table outside every location, the last
//    resort when nothing has room);
//  - containers stand only in regions (or in the hand, or "none"): never nested;
//  - no location holds more than its capacity (a container counts 1 in its
//    region, its contents count only in it);
//  - the planner's footprint rules (world/fit.hpp, applied exactly as
//    task::System applies them): a thing is only put where it fits (its x/y
//    size within the location's usable extent, no rotation), and only where
//    the cells of the things directly there plus its own stay within the
//    location's room. Only the initial placement may break them (accepted,
//    as the transition system accepts it): a thing that has not moved since
//    may stay where it does not fit, and a location over its room holds only
//    such unmoved things;
//  - an intervention is applied whole or refused with a reason, never partly,
//    never with an exception; a held thing is never silently deleted;
//  - for a given scenario, options and sequence of calls, everything (times,
//    failures) is the same on every run and platform.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "rtamp/exec/frame.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/exec/thing_layout.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/util/splitmix.hpp"
#include "rtamp/world/fit.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"
#include "rtamp/world/space_rules.hpp"
#include "rtamp/world/table.hpp"

namespace rtamp::exec {

// The phases of a move. Approach: hand -> thing; Grasp; Carry: thing ->
// destination; Place; Retreat (also the arm backing off after a halt with an
// empty gripper); Return: a held thing carried back and put down after a
// failure or a halt.
enum class Phase { Idle, Approach, Grasp, Carry, Place, Retreat, Return };
const NameTable<Phase>& phases();  // idle approach grasp carry place retreat return
const char* to_string(Phase p);

struct SymbolicWorldOptions {
  // Timing (seconds, metres). A phase lasts base + distance / speed, with
  // distances between the points of locations (a region's centre; a
  // container's point is its region's centre; home is the robot base +
  // home_height up).
  double approach_base = 0.5;  // approach = approach_base + d(hand, thing) / speed
  double grasp = 0.5;
  double carry_base = 0.5;  // carry = carry_base + d(thing, destination) / speed
  double place = 0.5;
  double retreat = 0.5;      // also the back-off after a halt with an empty gripper
  double return_base = 0.5;  // return = return_base + d(hand, target) / speed + place
  double speed = 0.25;       // m/s, approach, carry and return
  double home_height = 0.5;  // m above the robot base (task::kHomeHeight)

  // Failures. Each move fails with this probability, at the end of a phase
  // drawn uniformly from {Approach, Grasp, Carry, Place}.
  double failure_probability = 0;
  // Deterministic failures for tests: a move for which fails(m) is true fails
  // at the end of `fails_in` (Approach, Grasp, Carry or Place).
  std::function<bool(const Move&)> fails;
  Phase fails_in = Phase::Grasp;

  // Capacity of an added container whose class no scenario container has
  // (otherwise: the capacity of the first scenario container of its class).
  int added_container_capacity = 4;
  // The footprint rules; the planner's task::System uses the defaults
  // (task::System::Options::fit). Sizes: a scenario thing has its own; an
  // added container that of the first scenario container of its class (else
  // world::Container's default), an added object that of the first scenario
  // object of its class (else world::Object's default).
  world::FitRules fit;

  std::uint64_t seed = 1;
};

class SymbolicWorld final : public World, public Intervenable, public FrameSource {
 public:
  // Throws rtamp::Error if the scenario's initial placement breaks a
  // capacity or an option is out of range (an initial placement that breaks
  // the footprint rules is accepted, as task::System accepts it)
  // (durations < 0, speed <= 0, a probability outside [0, 1],
  // fails_in not one of the four failing phases, capacity < 1).
  explicit SymbolicWorld(const world::Scenario& scenario, SymbolicWorldOptions options = {});

  // --- exec::World
  double time() const override { return time_; }
  // Processes, in time order, every phase end due by time() + dt (within
  // 1 ns); dt <= 0 only processes what is due now. (A PersonWorld applies a
  // person's interventions between those, a phase end first at equal times.)
  void advance(double dt) override;
  double next_event_time() const override;
  world::Placement observe() override { return placement_; }
  // Begins the move, or fails it at once (poll() Failed with a reason) if the
  // thing is unknown, is not at m.from (when given), or m.to is unknown, the
  // thing itself, or a container for a container. Throws std::logic_error if a
  // move is running or the arm is busy (the contract forbids it).
  void start(const Move& m) override;
  MoveStatus poll(std::string* why) override;
  void halt() override;
  bool busy() override { return halted_ && phase_ != Phase::Idle; }
  std::string hand() const override { return hand_; }
  std::vector<WorldEvent> take_events() override;
  Intervenable* intervenable() override { return this; }
  FrameSource* frames() override { return this; }

  // --- exec::FrameSource: no joint angles; the hand point interpolated along
  // the moves; things laid out in their true locations (thing_layout.hpp).
  Frame frame(const world::Placement& perceived) override;

  // --- exec::Intervenable
  world::Placement true_placement() override { return placement_; }
  // Applies one intervention now (at time()), as a person would.
  WorldEvent apply(const world::Intervention& iv) override;

  // --- for tests and tools
  // The exact placement (a held thing at kInHand); observe() returns a copy.
  const world::Placement& truth() const { return placement_; }
  Phase phase() const { return phase_; }
  // When the current phase ends (infinity when Idle).
  double phase_end() const { return phase_ == Phase::Idle ? kInf : phase_end_; }
  // Where the hand is now (interpolated along approach, carry and return).
  world::Vec3 hand_point() const;
  // Every intervention applied or refused so far, in order.
  const std::vector<WorldEvent>& history() const { return history_; }
  // Capacity of a region or present container; -1 if there is none of that name.
  int capacity(const std::string& location) const;
  // The footprint rules in task::System's units (world/space_rules.hpp room
  // units): `thing` (present) fits `location` (a region or present container)
  // at all; its share of the location; the location's room (kRoomUnits); the
  // sum of the shares of the things directly at it. false / -1 for unknown names.
  bool fits(const std::string& thing, const std::string& location) const;
  std::int64_t cell(const std::string& thing, const std::string& location) const;
  std::int64_t room(const std::string& location) const;
  std::int64_t used(const std::string& location) const;
  // "" if `location` would take `thing` (present) now, else why not: the rules
  // every place, put-back and intervention follows (location kind, nesting,
  // fit, capacity, room: world/space_rules.hpp's refusal(), the rule book).
  std::string refusal(const std::string& thing, const std::string& location) const;
  // "" if every invariant of the header holds, else what is wrong (one line each).
  std::string check_invariants() const;

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  struct ContainerInfo {
    std::string cls;
    int capacity = 4;
    world::Vec3 size = world::Container{}.size;
  };
  // What the footprint rules need of a thing (present or about to be added).
  using Body = world::Body;

  // Locations and room.
  bool is_region(const std::string& loc) const;
  bool is_container(const std::string& name) const { return containers_.count(name) > 0; }
  int count_at(const std::string& loc, const std::string& except) const;
  std::int64_t used_at(const std::string& loc, const std::string& except) const;
  Body body_of(const std::string& thing) const;  // a present thing (an unknown one: a default object)
  Body new_body(const std::string& cls, bool container) const;  // an added thing of class `cls`
  world::Extent usable(const std::string& loc) const;           // a region or present container
  std::int64_t cell_of(const Body& b, const std::string& loc) const;  // its share of loc
  // `loc` can take `thing` (of body `b`) now: a region, or a container that is
  // present, not `thing`, not held, and `thing` is not a container; `thing`
  // fits it; and it has room (capacity and area).
  bool can_hold(const std::string& loc, const std::string& thing, const Body& b,
                std::string* why = nullptr) const;
  bool can_hold(const std::string& loc, const std::string& thing, std::string* why = nullptr) const {
    return can_hold(loc, thing, body_of(thing), why);
  }
  world::Vec3 point_of_location(const std::string& loc) const;
  world::Vec3 point_of_thing(const std::string& thing) const;
  // The valid location for `thing` closest to `p` (regions first on ties, then
  // declaration order); regions only if `regions_only`; "none" if nothing has room.
  std::string closest_valid(const std::string& thing, const world::Vec3& p, bool regions_only) const;
  void put(const std::string& thing, const std::string& loc, const world::Vec3& p);
  // `to`, else where `position` falls (for a container: the region), else "".
  std::string locate(const world::Intervention& iv, bool container) const;
  std::vector<std::string> location_names() const;  // regions then containers, declaration order

  // The move.
  void begin_phase(Phase p, double duration, const world::Vec3& from, const world::Vec3& to);
  void end_phase();
  void begin_return(const std::string& reason);
  void finish(MoveStatus s, const std::string& why);
  void lose_held(const std::string& why);  // a person took the held thing: the move ends Failed
  std::string held() const;                // the held thing, or ""

  // Interventions.
  WorldEvent apply_now(world::Intervention iv);
  void erase(const std::string& thing);
  void remove_container_spilling(const std::string& name, std::string* detail);

  SymbolicWorldOptions options_;
  std::vector<world::Region> regions_;
  std::map<std::string, ContainerInfo> containers_;
  std::vector<std::string> container_order_;  // declaration / addition order of present containers
  std::map<std::string, bool> class_is_container_;
  std::map<std::string, ContainerInfo> class_template_;  // first scenario container of each class
  std::map<std::string, world::Vec3> object_size_;        // present objects
  std::map<std::string, world::Vec3> class_object_size_;  // first scenario object of each class
  std::set<std::string> unmoved_;  // things at the location of the initial placement, never moved since
  world::Placement placement_;
  std::map<std::string, world::Vec3> loose_;  // points of things at "none"
  world::Geometry geometry_;                  // for interventions given by position
  world::TableTop table_;                     // a position off it is refused
  world::Vec3 home_{0, 0, 0};

  double time_ = 0;
  // The running move.
  Move move_;
  Phase phase_ = Phase::Idle;
  double phase_start_ = 0, phase_end_ = 0;
  world::Vec3 seg_from_{0, 0, 0}, seg_to_{0, 0, 0};
  std::string source_;  // where the thing was when the move began
  world::Vec3 source_point_{0, 0, 0};
  world::Vec3 dest_point_{0, 0, 0};  // the destination's point when last known
  std::optional<Phase> fail_at_;     // the phase at whose end the move fails
  std::string return_to_, return_reason_;
  bool halted_ = false;
  MoveStatus status_ = MoveStatus::Idle;
  std::string why_;
  std::string hand_;  // "" = home
  world::Vec3 hand_point_{0, 0, 0};

  // Interventions applied (reported by take_events(), kept in history()).
  SplitMix64 fail_rng_;
  std::unique_ptr<ThingLayout> layout_;  // for frame()
  std::vector<WorldEvent> pending_, history_;
};

}  // namespace rtamp::exec
