#include "rtamp/sim/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace rtamp::sim {

world::Geometry current_geometry(const Simulation& sim) {
  std::vector<world::Container> cs;
  for (std::size_t i = 0; i < sim.things().size(); ++i) {
    const Thing& t = sim.things()[i];
    if (!t.container || !t.present || t.name.empty() || sim.held() == static_cast<int>(i)) continue;
    const Eigen::Vector3d p = sim.position(static_cast<int>(i));
    int capacity = 8;
    if (const auto* c = sim.scenario().find_container(t.name)) capacity = c->capacity;
    cs.push_back({t.name, t.cls, {p.x(), p.y(), p.z()}, t.size, capacity, {}});
  }
  return world::Geometry(sim.scenario().regions, std::move(cs));
}

Eigen::Vector3d base_point(const Simulation& sim, int i) {
  const Thing& t = sim.thing(i);
  Eigen::Vector3d p = sim.position(i);
  if (!t.container) p.z() -= t.size[2] / 2;
  return p;
}

robot::ThingPose thing_pose(const Simulation& sim, int i) {
  const Eigen::Isometry3d pose = sim.pose(i);
  robot::ThingPose tp;
  tp.position = base_point(sim, i);
  tp.yaw = std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
  return tp;
}

std::string location_of(const Simulation& sim, const world::Geometry& g, int i) {
  const Eigen::Vector3d p = base_point(sim, i);
  if (sim.thing(i).container) return g.locate_region({p.x(), p.y(), p.z()});
  return g.locate({p.x(), p.y(), p.z()});
}

std::vector<int> contents_of(const Simulation& sim, int container) {
  std::vector<int> in;
  world::Geometry g = current_geometry(sim);
  const std::string& cname = sim.thing(container).name;
  if (sim.held() == container) {  // a tray in the hand holds what rides on it
    const Thing& c = sim.thing(container);
    const Eigen::Vector3d p = sim.position(container);
    g.add_container({cname, c.cls, {p.x(), p.y(), p.z()}, c.size, 8, {}});
  }
  for (std::size_t i = 0; i < sim.things().size(); ++i) {
    const Thing& t = sim.things()[i];
    if (t.container || !t.present || t.name.empty() || sim.held() == static_cast<int>(i)) continue;
    if (location_of(sim, g, static_cast<int>(i)) == cname) in.push_back(static_cast<int>(i));
  }
  return in;
}

int container_capacity(const Simulation& sim, int container) {
  const Thing& t = sim.thing(container);
  if (const auto* c = sim.scenario().find_container(t.name)) return c->capacity;
  for (const auto& c : sim.scenario().containers)
    if (c.cls == t.cls) return c.capacity;
  return 4;
}

std::string space_refusal(const Simulation& sim, const std::string& thing, const world::Body& body,
                          const std::string& location, const std::vector<int>& exclude) {
  world::LocationNow at;
  const world::FitRules rules;
  const int target = sim.find(location);
  if (const world::Region* r = sim.scenario().find_region(location)) {
    at.kind = world::LocationNow::Kind::Region;
    at.usable = world::usable_extent(*r);
    at.capacity = r->capacity;
  } else if (target >= 0 && sim.thing(target).container && sim.thing(target).present) {
    at.kind = world::LocationNow::Kind::Container;
    world::Container c;
    c.size = sim.thing(target).size;
    at.usable = world::usable_extent(c, rules);
    at.capacity = container_capacity(sim, target);
    at.held = sim.held() == target;
  }
  if (at.kind != world::LocationNow::Kind::Unknown) {
    const world::Geometry g = current_geometry(sim);
    for (std::size_t i = 0; i < sim.things().size(); ++i) {
      const Thing& t = sim.things()[i];
      const int ii = static_cast<int>(i);
      if (!t.present || t.name.empty() || sim.held() == ii || t.name == thing) continue;
      if (std::find(exclude.begin(), exclude.end(), ii) != exclude.end()) continue;
      if (location_of(sim, g, ii) != location) continue;
      ++at.count;
      at.used += world::cell_units({t.size, t.container}, at.usable, at.kind == world::LocationNow::Kind::Container,
                                   rules);
    }
  }
  return world::refusal(thing, body, location, at, rules);
}

std::optional<world::Vec3> free_spot(const Simulation& sim, const std::string& location, const world::Body& body,
                                     const std::vector<int>& exclude, double gap,
                                     const std::vector<world::Footprint>& keep_clear) {
  const world::Vec3& size = body.size;
  const world::Geometry g = current_geometry(sim);
  const int target = sim.find(location);
  const bool into_container = target >= 0 && sim.thing(target).container;
  std::vector<world::Footprint> occupied = keep_clear;
  if (sim.reserved_spot()) occupied.push_back(*sim.reserved_spot());
  for (std::size_t i = 0; i < sim.things().size(); ++i) {
    const Thing& t = sim.things()[i];
    const int ii = static_cast<int>(i);
    if (!t.present || t.name.empty() || sim.held() == ii) continue;
    if (std::find(exclude.begin(), exclude.end(), ii) != exclude.end()) continue;
    if (into_container && ii == target) continue;  // the tray itself is the area
    const Eigen::Vector3d p = sim.position(ii);
    // Things keep `gap` from each other (their footprints grow by it on every side);
    // from a tray standing in the area, at most 1.5 cm (only its rim is in the way).
    const double gg = t.container ? std::min(gap, world::kContainerGap) : gap;
    occupied.push_back(world::footprint_at({p.x(), p.y(), 0}, {t.size[0] + 2 * gg, t.size[1] + 2 * gg, 0}));
  }
  if (into_container) {
    // The rims are not floor: a thing must not overlap them.
    const Thing& c = sim.thing(target);
    const Eigen::Isometry3d cp = sim.pose(target);
    const double hx = c.size[0] / 2, hy = c.size[1] / 2, r = kTrayRim;
    const std::array<std::array<double, 4>, 4> rims{{{hx - r / 2, 0, r, c.size[1]},
                                                     {-hx + r / 2, 0, r, c.size[1]},
                                                     {0, hy - r / 2, c.size[0], r},
                                                     {0, -hy + r / 2, c.size[0], r}}};
    for (const auto& rim : rims) {
      const Eigen::Vector3d w = cp * Eigen::Vector3d(rim[0], rim[1], 0);
      const Eigen::Vector3d ext = (cp.linear() * Eigen::Vector3d(rim[2], rim[3], 0)).cwiseAbs();
      occupied.push_back(world::footprint_at({w.x(), w.y(), 0}, {ext.x(), ext.y(), 0}));
    }
  }
  const auto area = g.footprint_of(location);
  const auto surface = g.surface_z(location);
  if (!area || !surface) return std::nullopt;
  // Candidates: a 5 mm grid over the area, and the spots that touch an occupied
  // footprint's edge (so packing does not depend on the grid's step); the one nearest
  // an anchor wins (ties: smaller x, then smaller y). An object put into a region
  // packs from the region's corner nearest the robot's base (world/fit.hpp's room
  // rule: a grid from the corner), which keeps the middle free for a tray and the
  // reaches short; a container, and anything put into a container, goes nearest the
  // area's centre, with the grid centred there.
  const double step = 0.005;
  const double hx = (area->sx - size[0]) / 2, hy = (area->sy - size[1]) / 2;
  if (hx < 0 || hy < 0) return std::nullopt;
  const bool corner = !into_container && !body.container;
  const auto& base = sim.scenario().robot.base;
  const double dir_x = base[0] >= area->x ? 1 : -1, dir_y = base[1] >= area->y ? 1 : -1;
  const double ax = corner ? area->x + dir_x * hx : area->x, ay = corner ? area->y + dir_y * hy : area->y;
  // Offsets from the area's centre along one axis, sorted.
  auto offsets = [&](double h, double dir, double centre, bool x_axis) {
    std::vector<double> out;
    const int n = static_cast<int>(std::floor(h / step + 1e-9));
    if (corner) {
      const int m = static_cast<int>(std::floor(2 * h / step + 1e-9));
      for (int i = 0; i <= m; ++i) out.push_back(dir * (h - i * step));
      out.push_back(-dir * h);
    } else {
      for (int i = -n; i <= n; ++i) out.push_back(i * step);
    }
    const double half = (x_axis ? size[0] : size[1]) / 2;
    for (const auto& o : occupied)
      for (double e : {x_axis ? o.max_x() + half : o.max_y() + half, x_axis ? o.min_x() - half : o.min_y() - half})
        if (std::abs(e - centre) <= h + 1e-12) out.push_back(std::clamp(e - centre, -h, h));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
              out.end());
    return out;
  };
  const std::vector<double> xs = offsets(hx, dir_x, area->x, true), ys = offsets(hy, dir_y, area->y, false);
  std::optional<world::Vec3> best;
  double best_d = 0;
  for (double ox : xs) {
    for (double oy : ys) {
      const double x = area->x + ox, y = area->y + oy;
      const double d = std::hypot(x - ax, y - ay);
      if (best && d >= best_d - 1e-12) continue;
      const world::Footprint f = world::footprint_at({x, y, 0}, size);
      bool free = true;
      for (const auto& o : occupied)
        if (f.overlaps(o, -1e-9)) {  // touching (a spot exactly `gap` away) is free, despite rounding
          free = false;
          break;
        }
      if (!free) continue;
      best = world::Vec3{x, y, *surface};
      best_d = d;
    }
  }
  return best;
}

}  // namespace rtamp::sim
