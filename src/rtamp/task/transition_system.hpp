// The transition system TS = (S, s0, A, δ_t, Π, L) of the paper's Definition 1,
// for one set of regions, containers and objects (docs/design.md "Symbolic state",
// "Containers are objects and locations at once").
//
// Indexing (fixed for the lifetime of a System; names are the stable identity
// across rebuilds):
//   things    : objects 0..n-1, then containers n..n+C-1
//   locations : regions 0..R-1, then containers R..R+C-1 (container k is both
//               thing n+k and location R+k); location index R+C means "home"
//               and only occurs as the hand's location.
// Actions: move(t, l) picks thing t wherever it is and places it at l. It is
// enabled iff l is not t's current location, l is not t itself, a container is
// only placed in a region (containers do not nest), t's footprint fits l, the
// move is not forbidden, and l has room: fewer things directly at l than
// capacity(l) (a container counts 1 in its region, its contents count only in
// the container) and the room rule below holds. Moving a container carries
// its contents: their location stays the container. After move(t, l) the hand
// is at l. stay is always enabled and changes nothing. δ_t is deterministic.
//
// Footprints (world/fit.hpp and world/space_rules.hpp, the rule book, have the
// rules and why): things keep their orientation when placed (the skills do not
// rotate them), so t *fits* l iff t's x and y sizes are at most l's usable
// extents (a region's size; a container's size minus its rims) — exactly when
// world::free_spot() finds a spot in the empty location. *Room* is a grid
// share: t takes 1/k of l when k things of t's size fit l on the grid the
// arm packs them on (the skills' clearances kept), and move(t, l) needs
// used(l) + cell(t, l) <= room(l) = world::kRoomUnits. For things of one size
// it admits exactly what the arm places (measured, tests/sim/packing_test.cpp);
// for mixed sizes it is an estimate, and a place the arm then cannot make is
// reported by the executor and learnt through forbid_move(). Shares are
// integers (kRoomUnits / k rounded down: k of a kind fit, k + 1 never do).
// fits, cells and rooms are tabulated per (thing, location) at construction:
// for_each_move and enabled() do no geometry and no allocation.
//
// Forbidden moves (thing, location) are excluded from for_each_move and
// enabled() (a move that failed physically, fed back by the executor).
//
// Geometry used by motion-cost models (plan/motion_cost.hpp): the *point* of a
// region is its centre; of a container, the point of the region it stands in;
// of a thing, the point of its location; the hand's point is the point of its
// location, or the robot's home point (base + (0, 0, kHomeHeight)) before the
// first action. Positions inside a region are abstracted away, exactly as the
// TS abstracts them.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rtamp/task/state.hpp"
#include "rtamp/world/fit.hpp"
#include "rtamp/world/space_rules.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::task {

inline constexpr double kHomeHeight = 0.5;  // metres above the robot base
inline constexpr unsigned kMaxLocations = 254;  // regions + containers (fields of at most 8 bits)

class System {
 public:
  struct Options {
    bool ignore_capacity = false;  // ignore how much a location holds (capacity and room): diagnoses "capacity"
    bool ignore_geometry = false;  // every thing fits every location and rooms are unbounded
    world::FitRules fit;           // clearances and rims of the footprint rules
  };

  // Things and locations from the scenario; the initial state from
  // `placement` (every thing must be listed) and the hand's location `hand`
  // ("" or "home": home). Throws rtamp::Error on unknown names, things in no
  // location ("none") and containers inside containers. An over-full location
  // (by count or by room), or a thing where it does not fit, is accepted (a
  // person may have put it there): nothing more can be put there until things
  // are taken out; valid() reports it.
  System(const world::Scenario& scenario, const world::Placement& placement, const std::string& hand, Options options);
  System(const world::Scenario& scenario, const world::Placement& placement, const std::string& hand = {})
      : System(scenario, placement, hand, Options{}) {}
  // Initial placement from the scenario's positions (world::initial_placement), hand at home.
  explicit System(const world::Scenario& scenario);

  const world::Scenario& scenario() const { return scenario_; }
  const Layout& layout() const { return layout_; }
  const Options& options() const { return options_; }

  unsigned num_objects() const { return n_objects_; }
  unsigned num_containers() const { return n_containers_; }
  unsigned num_things() const { return n_objects_ + n_containers_; }
  unsigned num_regions() const { return n_regions_; }
  unsigned num_locations() const { return n_regions_ + n_containers_; }
  unsigned home() const { return num_locations(); }  // hand location before any action
  unsigned hand_field() const { return num_things(); }

  bool is_container(unsigned thing) const { return thing >= n_objects_; }
  unsigned location_of_container(unsigned thing) const { return n_regions_ + (thing - n_objects_); }
  bool is_container_location(unsigned loc) const { return loc >= n_regions_ && loc < num_locations(); }
  unsigned thing_of_location(unsigned loc) const { return n_objects_ + (loc - n_regions_); }

  const std::string& thing_name(unsigned t) const { return thing_names_[t]; }
  const std::string& thing_class(unsigned t) const { return thing_classes_[t]; }
  const std::string& location_name(unsigned l) const;  // "home" for home()
  std::uint64_t thing_uid(unsigned t) const { return uids_[t]; }  // hash of the name
  int find_thing(const std::string& name) const;
  int find_location(const std::string& name) const;  // regions and containers
  int capacity(unsigned loc) const { return capacities_[loc]; }
  // Footprint tables (see the header comment): t fits l at all; t's share of l
  // and l's room in room units (world::kRoomUnits; room is unbounded with
  // ignore_geometry, shares are then 0).
  bool fits(unsigned thing, unsigned loc) const { return fits_[thing * num_locations() + loc] != 0; }
  std::int64_t cell(unsigned thing, unsigned loc) const { return cells_[std::size_t{thing} * num_locations() + loc]; }
  std::int64_t room(unsigned loc) const { return rooms_[loc]; }

  // Forbidden moves. forbid_move(t, l) excludes move(t, l) from for_each_move
  // and enabled(); out-of-range indices are ignored. If t is in a symmetry
  // group it leaves it (it is no longer interchangeable). By name: unknown
  // names are ignored (the thing may be gone). Listed in the order forbidden.
  void forbid_move(unsigned thing, unsigned loc);
  void forbid_moves(const std::vector<std::pair<std::string, std::string>>& moves);
  bool forbidden(unsigned thing, unsigned loc) const;
  const std::vector<std::pair<unsigned, unsigned>>& forbidden_moves() const { return forbidden_; }
  // Two things have the same enabled-move rule (same fits row, cell and
  // forbidden moves, both objects or both containers): what symmetry needs
  // besides labels and costs.
  bool same_moves(unsigned a, unsigned b) const;

  std::uint32_t location(const State& s, unsigned thing) const { return layout_.get(s, thing); }
  std::uint32_t hand(const State& s) const { return layout_.get(s, hand_field()); }

  const State& initial() const { return initial_; }
  void set_initial(const State& s) { initial_ = s; }

  // Things directly at each location; `counts` has num_locations() entries.
  void occupancy(const State& s, int* counts) const;
  // Also the sum of their shares (room units) at each location, in `used`.
  void occupancy(const State& s, int* counts, std::int64_t* used) const;
  bool enabled(const State& s, const Action& a) const;
  State successor(const State& s, const Action& a) const;
  // Calls f(Action) for every enabled move (not stay), in a fixed order.
  template <class F>
  void for_each_move(const State& s, F&& f) const;
  // Symmetry (interchangeable objects): each group lists objects (not
  // containers) that nothing tells apart — same class, never named by a
  // proposition, the same moves (same_moves(): same footprint rules, no
  // forbidden move of their own), and a cost model that ignores which thing
  // it moves. set_symmetry() throws if members of a group differ in moves. The
  // planner searches the quotient: a *canonical* state has the locations of
  // each group's members in ascending order of member index, and
  // for_each_move skips a member whose predecessor in its group is at the same
  // location (its move would give the same canonical successor). Costs and
  // labels are invariant under permuting a group, so optimal costs are kept.
  void set_symmetry(const std::vector<std::vector<unsigned>>& groups);
  bool has_symmetry() const { return has_symmetry_; }
  int group_of(unsigned thing) const { return group_[thing]; }
  void canonicalize(State& s) const;
  State canonical(const State& s) const {
    State c = s;
    canonicalize(c);
    return c;
  }
  // successor() followed by canonicalisation (cheap: one member moved).
  State canonical_successor(const State& s, const Action& a) const;
  // Interchangeable containers (e.g. the trays of a class patrol): each group
  // lists containers that nothing tells apart — same class, never named by a
  // proposition as a thing or as a location, and same_containers(): the same
  // moves and capacity, and every object's moves into them alike. A
  // canonical state orders each group's members by a key of what each holds —
  // (its region, the hand in it or not, how many members of each object
  // group are in it, which other objects are in it) — and relabels the
  // locations of their contents and of the hand with them; objects are then
  // sorted as above. States that differ by permuting a group's containers
  // (their contents going with them) and the object groups have the same
  // canonical state, and labels, enabled moves and costs (a model that ignores
  // which thing it moves) are invariant under such permutations, so optimal
  // costs are kept. Members with equal keys hold interchangeable contents:
  // for_each_move offers only the first of them as a destination and as a
  // container to move. Throws on a group that is not interchangeable (the
  // symmetry is left as it was).
  void set_container_symmetry(const std::vector<std::vector<unsigned>>& groups);
  bool same_containers(unsigned a, unsigned b) const;
  int container_group_of(unsigned thing) const { return container_group_[thing]; }
  bool has_container_symmetry() const { return !container_groups_.empty(); }
  // Whether `loc` is the location of a container in a group.
  bool interchangeable_location(unsigned loc) const {
    return is_container_location(loc) && container_group_[thing_of_location(loc)] >= 0;
  }
  // The things canonical(s) puts in each place: src[t] is the thing of s
  // that becomes thing t (t itself outside container groups; objects of
  // object groups are not traced: any member at the place will do). `src`
  // has num_things() entries.
  void canonical_sources(const State& s, unsigned* src) const;

  // Capacities and rooms respected, no container in a container, fields in range.
  bool valid(const State& s) const;

  // Where every thing is, by name (the hand is hand_name(s)).
  world::Placement describe(const State& s) const;
  std::string hand_name(const State& s) const { return location_name(hand(s)); }
  // Throws rtamp::Error on unknown / missing names (capacities: see the constructor).
  State encode(const world::Placement& p, const std::string& hand = {}) const;
  std::string to_string(const State& s) const;      // "o1@r1 o2@tray hand@r2"
  std::string action_name(const Action& a) const;   // "move(o1, r2)" / "stay"

  // Geometry (see header comment).
  const world::Vec3& region_center(unsigned r) const { return scenario_.regions[r].center; }
  world::Vec3 location_point(const State& s, unsigned loc) const;
  world::Vec3 thing_point(const State& s, unsigned thing) const { return location_point(s, location(s, thing)); }
  world::Vec3 hand_point(const State& s) const;
  const world::Vec3& home_point() const { return home_point_; }

 private:
  // The groups of set_symmetry / set_container_symmetry, checked (transition_system.cpp).
  template <class Same>
  std::vector<std::vector<unsigned>> checked_groups(const std::vector<std::vector<unsigned>>& groups, bool containers,
                                                    Same same) const;
  void build_fit_tables();

  world::Scenario scenario_;
  Options options_;
  Layout layout_;
  unsigned n_objects_ = 0, n_containers_ = 0, n_regions_ = 0;
  std::vector<std::string> thing_names_, thing_classes_;
  std::vector<std::uint64_t> uids_;
  std::vector<int> capacities_;  // per location
  std::vector<std::uint8_t> fits_;    // [thing * num_locations() + loc]: fits (see fits())
  std::vector<std::uint8_t> allowed_;  // [thing * num_locations() + loc]: fits, legal kind, not forbidden
  std::vector<std::int64_t> cells_;    // [thing * num_locations() + loc]: its share of loc, room units
  std::vector<std::int64_t> rooms_;    // per location, room units (world::kRoomUnits)
  std::vector<std::pair<unsigned, unsigned>> forbidden_;
  world::Vec3 home_point_{0, 0, 0};
  State initial_;
  bool has_symmetry_ = false;
  std::vector<int> group_;                  // per thing: group index or -1
  std::vector<int> prev_, next_;            // per thing: neighbour in its group or -1
  std::vector<std::vector<unsigned>> groups_;
  std::vector<int> container_group_;        // per thing: container group index or -1
  std::vector<std::vector<unsigned>> container_groups_;
  // Orders the containers of each group by their keys (relabelling contents
  // and the hand); fills src (if not null) as canonical_sources() says.
  void order_containers(State& s, unsigned* src) const;
  // Per container: the first member of its group with the same key in s
  // (itself if none before it), for for_each_move.
  void container_twins(const State& s, unsigned* first) const;
};

template <class F>
void System::for_each_move(const State& s, F&& f) const {
  int counts[kMaxLocations + 1];
  std::int64_t used[kMaxLocations + 1];
  occupancy(s, counts, used);
  const unsigned L = num_locations();
  const bool bounded = !options_.ignore_capacity;
  // An interchangeable container with the same contents as an earlier member
  // of its group gives the same canonical successors, as a destination or moved.
  unsigned twin[kMaxLocations + 1];
  const bool containers = !container_groups_.empty();
  if (containers) container_twins(s, twin);
  for (unsigned t = 0; t < num_things(); ++t) {
    const std::uint32_t at = location(s, t);
    // An interchangeable twin at the same place gives the same canonical successors.
    if (has_symmetry_ && prev_[t] >= 0 && location(s, static_cast<unsigned>(prev_[t])) == at) continue;
    if (containers && is_container(t) && twin[t - n_objects_] != t) continue;
    const unsigned limit = is_container(t) ? n_regions_ : L;
    const std::uint8_t* row = allowed_.data() + std::size_t{t} * L;
    const std::int64_t* cell = cells_.data() + std::size_t{t} * L;
    for (unsigned l = 0; l < limit; ++l) {
      if (!row[l] || l == at) continue;
      if (containers && l >= n_regions_ && twin[l - n_regions_] != thing_of_location(l)) continue;
      if (bounded && (counts[l] >= capacities_[l] || used[l] + cell[l] > rooms_[l])) continue;
      f(Action::move(static_cast<std::uint16_t>(t), static_cast<std::uint16_t>(l)));
    }
  }
}

}  // namespace rtamp::task
