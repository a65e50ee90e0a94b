// What fits where: the footprint rules with which the transition system
// (task::System) and validate() decide whether a thing can be placed in a
// location at all, and whether a location has room left for it. They follow
// how the arm's skills place things (sim/skill_runner.cpp, sim/scene.cpp):
//  - A thing keeps its orientation when placed (the place skill keeps the
//    thing's yaw and searches spots for its unrotated x/y size), so there is no
//    90° rotation: a thing of size (sx, sy) fits an area (ax, ay) iff sx <= ax
//    and sy <= ay — exactly when world::free_spot() finds a spot in the empty area.
//  - The usable area of a region is its footprint; of a container, its
//    footprint minus its rims (`rim` on every side: a thing must not overlap them).
//  - Things the arm places keep `gap` from each other, and at least
//    min(gap, container_gap) from a container standing in the same region
//    (two containers keep min(gap, container_gap) from each other).
//  - Room (shares): a thing takes a share of a location, and the shares of the
//    things directly at a location sum to at most 1. Two measures enter it:
//    The grid: the arm places a thing at the free spot nearest an anchor
//    (sim/scene.cpp free_spot) — for an object put into a region, the
//    region's corner nearest the robot; for anything put into a container,
//    the container's centre — so things of one size d apart (d = gap for an
//    object, min(gap, container_gap) for a container) fill a grid from that
//    anchor, and an empty usable area (ux, uy) holds k = n(ux, sx) n(uy, sy)
//    things of size (sx, sy): from a corner n(u, s) = floor((u + d) / (s + d))
//    (a row of n needs n s + (n - 1) d <= u, and no arrangement of unrotated
//    copies keeping d does better); from the centre n(u, s) = 1 + 2
//    floor((u - s) / 2 / (s + d)) (the same number on either side).
//    The area bound: a thing takes the cell (sx + p)(sy + p), p = gap for an
//    object and 2 min(gap, container_gap) - gap for a container, of the room
//    (ux + gap)(uy + gap); growing every footprint by p / 2 per side turns an
//    arrangement that keeps the clearances into disjoint rectangles, so no
//    set whose cells exceed the room can be placed, and cell / room <= 1 / k.
//    The share is max(cell / room, just over 1 / (k + 1)): the least share
//    with which k things of one size fit and k + 1 never do, so for things of
//    one size the rule admits exactly what the arm places (measured for
//    objects in regions: tests/sim/packing_test.cpp, the table in
//    docs/scenario.md), and for mixed sizes it stays as near the area bound
//    as that allows. Mixed sets are an estimate that may err either way (no
//    rule of per-thing shares is exact), and so are containers in regions
//    (the arm sets them down nearest the region's centre, not on a grid); a
//    place the arm then cannot make is fed back to the planner (forbid_move).
// Not modelled: the finger room the skills keep clear by a tray's long rims,
// heights, reachability.
#pragma once

#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

// The clearances of space: one set of constants for the planner, both worlds,
// the arm's places (SkillRunnerOptions::place_gap) and the MuJoCo person's
// (sim/operator.cpp), and sim::free_spot's distance kept from a tray.
inline constexpr double kPlaceGap = 0.035;      // m, between two things (room for the fingers)
inline constexpr double kContainerGap = 0.015;  // m, kept from a container standing in the same region
inline constexpr double kContainerRim = 0.008;  // m, rim thickness of a container (sim's kTrayRim)

struct FitRules {
  double gap = kPlaceGap;                // m, between two things the arm places
  double container_gap = kContainerGap;  // m, kept from a container standing in the same region
  double rim = kContainerRim;            // m, rim thickness of a container (every side)
};

// x, y extents of an area.
struct Extent {
  double x = 0, y = 0;
};

Extent usable_extent(const Region& r);
Extent usable_extent(const Container& c, const FitRules& rules = {});

// A thing of `size` (x, y used) can be placed in an empty area of `area` (no rotation).
bool fits(const Vec3& size, const Extent& area);

// The grid above: how many things of `size` (containers if `container`) an
// empty area of `usable` holds, from a corner or, if `centred`, from its
// centre; 0 if one does not fit (at most 1e6).
int grid_count(const Vec3& size, bool container, bool centred, const Extent& usable, const FitRules& rules = {});

// The area bound above: a thing's cell and an area's room, in m².
double cell_area(const Vec3& size, bool container, const FitRules& rules = {});
double room_area(const Extent& usable, const FitRules& rules = {});

}  // namespace rtamp::world
