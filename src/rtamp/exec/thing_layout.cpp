#include "rtamp/exec/thing_layout.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/world/geometry.hpp"

namespace rtamp::exec {

namespace {
constexpr double kGap = 0.02;        // m between cells
constexpr double kTrayFloor = 0.01;  // things in a tray stand on its floor
const char* const kHand = "hand";
}  // namespace

ThingLayout::ThingLayout(const world::Scenario& scenario)
    : scenario_(scenario), initial_(world::initial_placement(scenario)) {
  for (const auto& c : scenario.containers) {
    sizes_[c.name] = c.size;
    spots_[c.name] = Spot{*initial_.location_of(c.name), c.position, {0, 0, 0}};
  }
  for (const auto& o : scenario.objects) {
    sizes_[o.name] = o.size;
    Spot s{*initial_.location_of(o.name), o.position, {0, 0, 0}};
    if (const world::Container* c = scenario.find_container(s.location))
      s.offset = {o.position[0] - c->position[0], o.position[1] - c->position[1], 0};
    spots_[o.name] = s;
  }
}

world::Vec3 ThingLayout::size(const std::string& thing, const std::string& cls, bool container) const {
  if (auto it = sizes_.find(thing); it != sizes_.end()) return it->second;
  if (container) {
    for (const auto& c : scenario_.containers)
      if (c.cls == cls) return c.size;
    return world::Container{}.size;
  }
  for (const auto& o : scenario_.objects)
    if (o.cls == cls) return o.size;
  return world::Object{}.size;
}

world::Vec3 ThingLayout::free_cell(const std::string& thing, const world::Vec3& sz, const world::Vec3& centre,
                                   const world::Vec3& extent, const world::Placement& p, bool relative) {
  // Cells of the thing's size plus a gap, row by row from the footprint's corner.
  const double px = sz[0] + kGap, py = sz[1] + kGap;
  const int nx = std::max(1, static_cast<int>(std::floor(extent[0] / px)));
  const int ny = std::max(1, static_cast<int>(std::floor(extent[1] / py)));
  const std::string& loc = p.things.at(thing).location;
  for (int k = 0; k < nx * ny; ++k) {
    const double x = -extent[0] / 2 + px * (k % nx + 0.5), y = -extent[1] / 2 + py * (k / nx + 0.5);
    const world::Vec3 cand = relative ? world::Vec3{x, y, 0} : world::Vec3{centre[0] + x, centre[1] + y, centre[2]};
    bool taken = false;
    for (const auto& [n, t] : p.things) {
      if (n == thing || t.location != loc) continue;
      auto it = spots_.find(n);
      if (it == spots_.end() || it->second.location != loc) continue;
      const world::Vec3& o = relative ? it->second.offset : it->second.pos;
      const world::Vec3 os = size(n, t.cls, t.container);
      if (std::abs(o[0] - cand[0]) < (os[0] + sz[0]) / 2 && std::abs(o[1] - cand[1]) < (os[1] + sz[1]) / 2)
        taken = true;
    }
    if (!taken) return cand;
  }
  return relative ? world::Vec3{0, 0, 0} : centre;  // full: the middle
}

void ThingLayout::update(const world::Placement& p, const std::optional<world::Vec3>& hand) {
  for (auto it = spots_.begin(); it != spots_.end();) it = p.things.count(it->first) ? std::next(it) : spots_.erase(it);
  // Containers first (their contents are placed relative to them).
  for (int pass = 0; pass < 2; ++pass) {
    for (const auto& [name, t] : p.things) {
      if (t.container != (pass == 0)) continue;
      Spot& s = spots_[name];
      const world::Vec3 sz = size(name, t.cls, t.container);
      if (t.location == kHand) {
        s.location = kHand;
        if (hand) s.pos = {(*hand)[0], (*hand)[1], (*hand)[2] - sz[2] / 2};
        continue;
      }
      if (s.location == t.location) continue;
      if (t.location == world::kNoLocation) {
        s.location = t.location;
        continue;
      }
      s.location = t.location;
      if (const world::Region* r = scenario_.find_region(t.location)) {
        s.pos = free_cell(name, sz, r->center, r->size, p, false);
      } else if (p.things.count(t.location)) {
        const auto& ct = p.things.at(t.location);
        const world::Vec3 csz = size(t.location, ct.cls, true);
        s.offset = free_cell(name, sz, {0, 0, 0}, {csz[0] - 0.02, csz[1] - 0.02, 0}, p, true);
      }
    }
  }
  // Absolute positions of things in containers.
  for (const auto& [name, t] : p.things) {
    if (t.container || !p.things.count(t.location)) continue;
    Spot& s = spots_[name];
    const Spot& c = spots_[t.location];
    s.pos = {c.pos[0] + s.offset[0], c.pos[1] + s.offset[1], c.pos[2] + kTrayFloor};
  }
}

world::Vec3 ThingLayout::position(const std::string& thing) const {
  auto it = spots_.find(thing);
  return it == spots_.end() ? world::Vec3{0, 0, 0} : it->second.pos;
}

Frame ThingLayout::frame(double t, const world::Placement& p, const world::Vec3& hand) {
  update(p, hand);
  Frame f;
  f.t = t;
  f.tool = hand;
  for (const auto& [name, th] : p.things) {
    if (th.location == "hand") f.held = name;
    Frame::Thing ft;
    ft.name = name;
    ft.cls = th.cls;
    ft.container = th.container;
    ft.size = size(name, th.cls, th.container);
    ft.pos = position(name);
    ft.at = th.location;
    f.things.push_back(std::move(ft));
  }
  return f;
}

}  // namespace rtamp::exec
