#include "rtamp/world/space_rules.hpp"

#include <cmath>
#include <cstdio>

namespace rtamp::world {

namespace {

std::string metres(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}

std::string percent(std::int64_t units) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f %%", 100.0 * static_cast<double>(units) / static_cast<double>(kRoomUnits));
  return b;
}

}  // namespace

std::int64_t cell_units(const Body& b, const Extent& usable, bool into_container, const FitRules& rules) {
  const int k = grid_count(b.size, b.container, into_container, usable, rules);
  const double area = std::min(1.0, cell_area(b.size, b.container, rules) / room_area(usable, rules));
  const auto area_share = static_cast<std::int64_t>(std::floor(area * static_cast<double>(kRoomUnits)));
  if (k == 0) return area_share;  // it does not fit (an initial placement may put it there)
  const std::int64_t share = std::max(area_share, kRoomUnits / (k + 1) + 1);
  return std::min(share, kRoomUnits / k);  // k always fit (cell / room <= 1 / k up to rounding)
}

std::string refusal(std::string_view thing_name, const Body& b, std::string_view loc_name, const LocationNow& at,
                    const FitRules& rules) {
  const std::string thing(thing_name), loc(loc_name);
  if (at.kind == LocationNow::Kind::Unknown) return loc.empty() ? "no location" : loc + " is not a location in the world";
  if (at.kind == LocationNow::Kind::Container) {
    if (loc == thing) return thing + " cannot go into itself";
    if (b.container) return thing + " is a container and " + loc + " is one: containers do not nest";
    if (at.held) return loc + " is in the gripper";
  }
  if (!fits(b.size, at.usable))
    return thing + " does not fit in " + loc + " (" + metres(b.size[0]) + " x " + metres(b.size[1]) + " m; usable " +
           metres(at.usable.x) + " x " + metres(at.usable.y) + " m)";
  if (at.count >= at.capacity) return loc + " has no room (capacity " + std::to_string(at.capacity) + ")";
  const bool into_container = at.kind == LocationNow::Kind::Container;
  const std::int64_t need = cell_units(b, at.usable, into_container, rules);
  if (at.used + need > kRoomUnits)
    return loc + " has no room for " + thing + " (it takes " + percent(need) + " of " + loc + "; " + percent(at.used) +
           " is taken)";
  return "";
}

Body body_of(const Scenario& s, std::string_view thing) {
  for (const Container& c : s.containers)
    if (c.name == thing) return {c.size, true};
  for (const Object& o : s.objects)
    if (o.name == thing) return {o.size, false};
  return {};
}

Body new_body(const Scenario& s, std::string_view cls, bool container) {
  if (container) {
    for (const Container& c : s.containers)
      if (c.cls == cls) return {c.size, true};
    return {Container{}.size, true};
  }
  for (const Object& o : s.objects)
    if (o.cls == cls) return {o.size, false};
  return {Object{}.size, false};
}

LocationNow location_now(const Scenario& s, const Placement& p, std::string_view loc, std::string_view without,
                         const FitRules& rules) {
  LocationNow at;
  if (const Region* r = s.find_region(std::string(loc))) {
    at.kind = LocationNow::Kind::Region;
    at.usable = usable_extent(*r);
    at.capacity = r->capacity;
  } else if (const Container* c = s.find_container(std::string(loc)); c && p.things.count(c->name)) {
    at.kind = LocationNow::Kind::Container;
    at.usable = usable_extent(*c, rules);
    at.capacity = c->capacity;
  } else {
    return at;
  }
  for (const auto& [name, t] : p.things) {
    if (t.location != loc || name == without) continue;
    ++at.count;
    at.used += cell_units(body_of(s, name), at.usable, at.kind == LocationNow::Kind::Container, rules);
  }
  return at;
}

}  // namespace rtamp::world
