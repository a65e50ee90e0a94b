// The rule book of space: whether a location can take a thing now —
// the one decision behind the symbolic world's places, put-backs and
// interventions (exec/symbolic_world.cpp), the MuJoCo person's additions and
// relocations and the MuJoCo arm's places (sim/scene.hpp space_refusal), and a
// planner change (world/change.hpp check_change_room), so that every world
// refuses the same things with the same words. The transition system
// (task::System) applies the same rules as precomputed tables: cell_units()
// are its integers.
//
// Rules, in the order they are checked (the first broken one is the refusal):
//  1. the location is a region or a present container; a thing never goes
//     into itself, a container never into a container (no nesting), nothing
//     into a container that is in the gripper;
//  2. fit (world/fit.hpp): the thing's x/y size within the location's usable
//     extent, no rotation;
//  3. capacity: fewer things directly at the location than its capacity (a
//     container counts 1 in its region, its contents count only in it);
//  4. room (fit.hpp's shares): the shares of the things directly there plus
//     the thing's own within the whole location, in room units (a location is
//     kRoomUnits; a thing of which k fit on the arm's grid takes the larger of
//     its area share and kRoomUnits / (k + 1) + 1, at most kRoomUnits / k: k
//     of one size always fit, k + 1 never do).
// A location's state is given "without the thing": what is there if the thing
// is not (so asking about where a thing already is asks whether it may stay).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "rtamp/world/fit.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

inline constexpr std::int64_t kRoomUnits = std::int64_t{1} << 40;  // the whole room of a location

// What the rules need of a thing: its size (x, y used) and whether it is a container.
struct Body {
  Vec3 size = Object{}.size;
  bool container = false;
};

// A location as the rules see it now, without the thing being asked about.
struct LocationNow {
  enum class Kind { Unknown, Region, Container };
  Kind kind = Kind::Unknown;
  Extent usable;          // usable_extent() of the region or container
  int capacity = 0;       // the location's capacity
  int count = 0;          // things directly there
  std::int64_t used = 0;  // the sum of their cell_units() here
  bool held = false;      // a container that is in the gripper
};

// The share of a location of `usable` extent (a container if `into_container`)
// that a thing of body `b` takes, in room units (its area share if it does not fit).
std::int64_t cell_units(const Body& b, const Extent& usable, bool into_container, const FitRules& rules = {});

// "" if `location` (named `loc`, in state `at`) may take `thing` (of body `b`)
// now, else why not, one line naming the thing and the location, e.g.
// "r2 has no room (capacity 2)".
std::string refusal(std::string_view thing, const Body& b, std::string_view loc, const LocationNow& at,
                    const FitRules& rules = {});

// The rules' view of a scenario's world whose things are where `p` says (sizes and
// capacities from `s`; a location or thing `s` does not declare is Unknown / a default
// object): location `loc` without thing `without`.
LocationNow location_now(const Scenario& s, const Placement& p, std::string_view loc, std::string_view without,
                         const FitRules& rules = {});
// A thing of `s` (an object's or container's size; a default object if unknown).
Body body_of(const Scenario& s, std::string_view thing);
// A thing added with class `cls`: the size of the first thing of that class in `s`,
// else world::Object's or world::Container's default (as the symbolic world adds one).
Body new_body(const Scenario& s, std::string_view cls, bool container);

}  // namespace rtamp::world
