#include "rtamp/world/fit.hpp"

#include <algorithm>
#include <cmath>

namespace rtamp::world {

Extent usable_extent(const Region& r) { return {r.size[0], r.size[1]}; }

Extent usable_extent(const Container& c, const FitRules& rules) {
  return {std::max(0.0, c.size[0] - 2 * rules.rim), std::max(0.0, c.size[1] - 2 * rules.rim)};
}

// The same test as free_spot()'s grid (room for the centre >= 0 on both axes).
bool fits(const Vec3& size, const Extent& area) { return area.x - size[0] >= 0 && area.y - size[1] >= 0; }

int grid_count(const Vec3& size, bool container, bool centred, const Extent& usable, const FitRules& rules) {
  if (!fits(size, usable)) return 0;
  const double d = container ? std::min(rules.gap, rules.container_gap) : rules.gap;
  // 1e-9: a row that fits exactly counts despite the rounding of the sums.
  auto n = [&](double u, double s) {
    if (centred) return 1 + 2 * std::floor((u - s) / 2 / (s + d) + 1e-9);
    return std::max(1.0, std::floor((u + d) / (s + d) + 1e-9));
  };
  const double k = n(usable.x, size[0]) * n(usable.y, size[1]);
  return k > 1e6 ? 1'000'000 : static_cast<int>(k);
}

double cell_area(const Vec3& size, bool container, const FitRules& rules) {
  const double p = container ? 2 * std::min(rules.gap, rules.container_gap) - rules.gap : rules.gap;
  return std::max(0.0, size[0] + p) * std::max(0.0, size[1] + p);
}

double room_area(const Extent& usable, const FitRules& rules) {
  return (usable.x + rules.gap) * (usable.y + rules.gap);
}

}  // namespace rtamp::world
