#include "rtamp/world/fit.hpp"

#include <algorithm>

namespace rtamp::world {

Extent usable_extent(const Region& r) { return {r.size[0], r.size[1]}; }

Extent usable_extent(const Container& c, const FitRules& rules) {
  return {std::max(0.0, c.size[0] - 2 * rules.rim), std::max(0.0, c.size[1] - 2 * rules.rim)};
}

// The same test as free_spot()'s grid (room for the centre >= 0 on both axes).
bool fits(const Vec3& size, const Extent& area) { return area.x - size[0] >= 0 && area.y - size[1] >= 0; }

double cell_area(const Vec3& size, bool container, const FitRules& rules) {
  const double p = container ? 2 * std::min(rules.gap, rules.container_gap) - rules.gap : rules.gap;
  return std::max(0.0, size[0] + p) * std::max(0.0, size[1] + p);
}

double room_area(const Extent& usable, const FitRules& rules) {
  return (usable.x + rules.gap) * (usable.y + rules.gap);
}

}  // namespace rtamp::world
