#include "rtamp/world/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtamp::world {

bool Footprint::contains_point(double px, double py, double margin) const {
  return px >= min_x() - margin && px <= max_x() + margin && py >= min_y() - margin && py <= max_y() + margin;
}

bool Footprint::contains(const Footprint& o) const {
  return o.min_x() >= min_x() && o.max_x() <= max_x() && o.min_y() >= min_y() && o.max_y() <= max_y();
}

bool Footprint::overlaps(const Footprint& o, double gap) const {
  const double dx = std::abs(x - o.x) - (sx + o.sx) / 2;
  const double dy = std::abs(y - o.y) - (sy + o.sy) / 2;
  return dx < gap && dy < gap;
}

Footprint footprint_at(const Vec3& c, const Vec3& size) { return Footprint{c[0], c[1], size[0], size[1]}; }
Footprint footprint(const Region& r) { return footprint_at(r.center, r.size); }
Footprint footprint(const Container& c) { return footprint_at(c.position, c.size); }
Footprint footprint(const Object& o) { return footprint_at(o.position, o.size); }

double surface_height(const Region& r) { return r.center[2]; }
double surface_height(const Container& c) { return c.position[2] + std::min(c.size[2], kContainerFloor); }

namespace {

bool finite(double v) { return std::isfinite(v); }

constexpr double kSpotTolerance = 1e-9;  // m

// Centres of a grid with spacing `step` along an axis of length `free` (the
// room left for the thing's centre), centred on 0; at most `limit` points.
std::vector<double> axis_points(double free, double step, int limit) {
  std::vector<double> pts;
  if (free < 0) return pts;
  int n = static_cast<int>(std::floor(free / step + 1e-9)) + 1;
  n = std::clamp(n, 1, limit);
  const double span = (n - 1) * step;
  for (int i = 0; i < n; ++i) pts.push_back(-span / 2 + i * step);
  return pts;
}

std::optional<Vec3> search(const Footprint& area, double z, const std::vector<Footprint>& occupied, const Vec3& size,
                           double gap, double step_x, double step_y, int limit) {
  const std::vector<double> xs = axis_points(area.sx - size[0], step_x, limit);
  const std::vector<double> ys = axis_points(area.sy - size[1], step_y, limit);
  struct Cand {
    long long key;  // squared distance to the centre in nm^2-ish units: ties are exact
    double dx, dy;
  };
  std::vector<Cand> cands;
  cands.reserve(xs.size() * ys.size());
  for (double dy : ys)
    for (double dx : xs) cands.push_back({std::llround((dx * dx + dy * dy) * 1e9), dx, dy});
  std::stable_sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.key < b.key; });
  for (const Cand& c : cands) {
    Footprint f{area.x + c.dx, area.y + c.dy, size[0], size[1]};
    if (!area.contains(f)) continue;  // rounding at the edges
    bool free = true;
    for (const Footprint& o : occupied)
      if (f.overlaps(o, gap - kSpotTolerance)) {  // exactly `gap` apart is free, despite rounding
        free = false;
        break;
      }
    if (free) return Vec3{f.x, f.y, z};
  }
  return std::nullopt;
}

}  // namespace

std::optional<Vec3> free_spot(const Footprint& area, double surface_z, const std::vector<Footprint>& occupied,
                              const Vec3& size, double gap) {
  if (!(size[0] > 0 && size[1] > 0 && finite(size[0]) && finite(size[1]))) return std::nullopt;
  if (!(area.sx > 0 && area.sy > 0 && finite(area.x) && finite(area.y) && finite(area.sx) && finite(area.sy)))
    return std::nullopt;
  if (!(gap >= 0) || !finite(gap)) gap = 0;
  const double px = size[0] + gap, py = size[1] + gap;
  if (auto spot = search(area, surface_z, occupied, size, gap, px, py, 1000)) return spot;
  const double fine = std::min(px, py) / 4;
  return search(area, surface_z, occupied, size, gap, fine, fine, 200);
}

Geometry::Geometry(const Scenario& s) : regions_(s.regions), containers_(s.containers) {}

Geometry::Geometry(std::vector<Region> regions, std::vector<Container> containers)
    : regions_(std::move(regions)), containers_(std::move(containers)) {}

bool Geometry::move_container(const std::string& name, const Vec3& position) {
  for (Container& c : containers_)
    if (c.name == name) {
      c.position = position;
      return true;
    }
  return false;
}

void Geometry::add_container(Container c) {
  for (Container& existing : containers_)
    if (existing.name == c.name) {
      existing = std::move(c);
      return;
    }
  containers_.push_back(std::move(c));
}

bool Geometry::remove_container(const std::string& name) {
  auto it = std::find_if(containers_.begin(), containers_.end(), [&](const Container& c) { return c.name == name; });
  if (it == containers_.end()) return false;
  containers_.erase(it);
  return true;
}

std::string Geometry::locate(const Vec3& p) const {
  const Container* best = nullptr;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const Container& c : containers_) {
    if (p[2] < c.position[2] - kBelowTolerance) continue;
    const Footprint f = footprint(c);
    const bool below_rim = p[2] <= c.position[2] + c.size[2];
    if (!f.contains_point(p[0], p[1], below_rim ? kRimMargin : 0.0)) continue;
    const double dx = p[0] - c.position[0], dy = p[1] - c.position[1];
    const double d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {
      best = &c;
      best_d2 = d2;
    }
  }
  if (best) return best->name;
  return locate_region(p);
}

std::string Geometry::locate_region(const Vec3& p) const {
  for (const Region& r : regions_)
    if (p[2] >= r.center[2] - kBelowTolerance && footprint(r).contains_point(p[0], p[1])) return r.name;
  return kNoLocation;
}

const Region* Geometry::region(std::string_view name) const {
  for (const Region& r : regions_)
    if (r.name == name) return &r;
  return nullptr;
}

const Container* Geometry::container(std::string_view name) const {
  for (const Container& c : containers_)
    if (c.name == name) return &c;
  return nullptr;
}

std::optional<Footprint> Geometry::footprint_of(std::string_view location) const {
  if (const Container* c = container(location)) return footprint(*c);
  if (const Region* r = region(location)) return footprint(*r);
  return std::nullopt;
}

std::optional<double> Geometry::surface_z(std::string_view location) const {
  if (const Container* c = container(location)) return surface_height(*c);
  if (const Region* r = region(location)) return surface_height(*r);
  return std::nullopt;
}

std::optional<Vec3> Geometry::free_spot(std::string_view location, const std::vector<Footprint>& occupied,
                                        const Vec3& size, double gap) const {
  const auto area = footprint_of(location);
  if (!area) return std::nullopt;
  return world::free_spot(*area, *surface_z(location), occupied, size, gap);
}

Placement initial_placement(const Scenario& s) {
  const Geometry g(s);
  Placement p;
  for (const Container& c : s.containers) p.set(c.name, g.locate_region(c.position), c.cls, true);
  for (const Object& o : s.objects) p.set(o.name, g.locate(o.position), o.cls, false);
  return p;
}

}  // namespace rtamp::world
