// The geometric abstraction: how continuous positions map to the symbolic
// locations of the paper's transition system (Section II: "objects are placed
// in m discrete and non-overlapping regions which we achieve by abstractly
// partitioning a continuous 3D workspace"). The planner uses it to read the
// initial state of a scenario; perception (sim layer) uses the same rules to
// map observed poses to locations, so both always agree.
//
// Rules (all footprints are axis-aligned rectangles in x, y):
//  - A region holds the points inside its footprint (edges included) that are
//    no more than kBelowTolerance below its centre's z. Regions never overlap
//    (validate() checks), so at most one region holds a point.
//  - A container (tray) at `position` with size (sx, sy, h) holds the points
//    inside its footprint at any height from kBelowTolerance below its base
//    upwards; at or below its rim (z <= position.z + h) the footprint is grown
//    by kRimMargin on every side (a block leaning on the rim is still in the
//    tray); above the rim only the exact footprint counts.
//  - Container footprints take precedence over regions. If several containers
//    hold a point, the one whose centre is nearest (in x, y) wins, then the
//    first declared.
//  - A point no location holds is in kNoLocation ("none"); a container's own
//    location is the region holding its position (containers do not nest).
//  - Things rest on a location's surface: a region's centre z, or a
//    container's floor top, position.z + min(h, kContainerFloor).
//
// Invariant of free_spot(): a returned spot's footprint (size x, y) lies
// inside the location's footprint and keeps at least `gap` from every
// occupied footprint in x or y (footprints never overlap).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/world/fit.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

inline constexpr const char* kNoLocation = "none";
inline constexpr double kBelowTolerance = 0.02;  // m
inline constexpr double kRimMargin = 0.01;       // m
inline constexpr double kContainerFloor = 0.01;  // m, floor thickness of a tray

// An axis-aligned rectangle: centre (x, y), extents (sx, sy).
struct Footprint {
  double x = 0, y = 0, sx = 0, sy = 0;

  double min_x() const { return x - sx / 2; }
  double max_x() const { return x + sx / 2; }
  double min_y() const { return y - sy / 2; }
  double max_y() const { return y + sy / 2; }
  // (px, py) inside the rectangle grown by `margin` (edges included).
  bool contains_point(double px, double py, double margin = 0) const;
  // `o` lies entirely inside this rectangle (edges may touch).
  bool contains(const Footprint& o) const;
  // The interiors come closer than `gap` in both x and y (gap 0: they overlap
  // with positive area; touching edges do not count).
  bool overlaps(const Footprint& o, double gap = 0) const;
  bool operator==(const Footprint&) const = default;
};

Footprint footprint_at(const Vec3& centre, const Vec3& size);
Footprint footprint(const Region& r);
Footprint footprint(const Container& c);
Footprint footprint(const Object& o);

double surface_height(const Region& r);
double surface_height(const Container& c);

// A grid search for a free spot in `area` (surface at height `surface_z`) for
// a thing of `size`: first a regular grid of pitch size + gap, centred in the
// area, nearest-to-centre first; if all of it is taken, a finer grid (a quarter
// pitch). Returns the centre of the thing's base, or nullopt if nothing fits.
std::optional<Vec3> free_spot(const Footprint& area, double surface_z, const std::vector<Footprint>& occupied,
                              const Vec3& size, double gap = kPlaceGap);

// Regions and containers (with containers' current positions), answering
// "which location holds this point".
class Geometry {
 public:
  Geometry() = default;
  explicit Geometry(const Scenario& s);  // containers at their initial positions
  Geometry(std::vector<Region> regions, std::vector<Container> containers);

  const std::vector<Region>& regions() const { return regions_; }
  const std::vector<Container>& containers() const { return containers_; }

  // Updates a container's position (it was moved, with its contents). False if unknown.
  bool move_container(const std::string& name, const Vec3& position);
  void add_container(Container c);
  bool remove_container(const std::string& name);

  // The location holding `p` (a container name, a region name, or "none").
  std::string locate(const Vec3& p) const;
  // The region holding `p`, or "none" (where a container standing at p is).
  std::string locate_region(const Vec3& p) const;

  // The footprint and surface height of a region or container; nullopt if unknown.
  std::optional<Footprint> footprint_of(std::string_view location) const;
  std::optional<double> surface_z(std::string_view location) const;

  // free_spot() in a named location; nullopt if it is unknown or full.
  std::optional<Vec3> free_spot(std::string_view location, const std::vector<Footprint>& occupied, const Vec3& size,
                                double gap = kPlaceGap) const;

 private:
  const Region* region(std::string_view name) const;
  const Container* container(std::string_view name) const;

  std::vector<Region> regions_;
  std::vector<Container> containers_;
};

// The symbolic state of a scenario at time 0: the location of every object
// (by geometry, containers at their initial positions) and every container
// (the region under it), with classes.
Placement initial_placement(const Scenario& s);

}  // namespace rtamp::world
