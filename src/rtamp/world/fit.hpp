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
//    min(gap, container_gap) from a container standing in the same region.
//  - Room (an area bound): a thing t at a location takes the cell
//    (sx + p_t)(sy + p_t) with p_t = gap for an object and
//    p_t = 2 min(gap, container_gap) - gap for a container (a cell side is
//    never below 0); a location offers (ux + gap)(uy + gap) for a usable area
//    (ux, uy). Growing every footprint by p_t / 2 per side turns any
//    arrangement that keeps those clearances into disjoint rectangles inside
//    the usable area grown by gap / 2, so: if the cells of the things at a
//    location exceed its room, no such arrangement exists (the bound is a
//    necessary condition; it may admit sets that a greedy spot search cannot
//    place).
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

// The area bound above, in m².
double cell_area(const Vec3& size, bool container, const FitRules& rules = {});
double room_area(const Extent& usable, const FitRules& rules = {});

}  // namespace rtamp::world
