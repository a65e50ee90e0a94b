#include "rtamp/world/table.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/util/format.hpp"

namespace rtamp::world {

TableTop table_top(const Scenario& s) {
  double xmin = s.robot.base[0] - 0.25, xmax = s.robot.base[0] + 0.25;
  double ymin = s.robot.base[1] - 0.25, ymax = s.robot.base[1] + 0.25;
  auto grow = [&](const Vec3& c, const Vec3& sz) {
    xmin = std::min(xmin, c[0] - sz[0] / 2);
    xmax = std::max(xmax, c[0] + sz[0] / 2);
    ymin = std::min(ymin, c[1] - sz[1] / 2);
    ymax = std::max(ymax, c[1] + sz[1] / 2);
  };
  for (const auto& r : s.regions) grow(r.center, r.size);
  for (const auto& c : s.containers) grow(c.position, c.size);
  for (const auto& o : s.objects) grow(o.position, o.size);
  return {xmin - 0.15, xmax + 0.15, ymin - 0.15, ymax + 0.15};
}

std::string off_table(const TableTop& top, const Vec3& p) {
  const std::string at =
      "position [" + format_number(p[0]) + ", " + format_number(p[1]) + ", " + format_number(p[2]) + "]";
  if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && top.contains(p[0], p[1])))
    return at + " is off the table (x in [" + format_number(top.xmin) + ", " + format_number(top.xmax) +
           "], y in [" + format_number(top.ymin) + ", " + format_number(top.ymax) + "])";
  if (!(p[2] >= -kUnderTableTolerance && std::isfinite(p[2]))) return at + " is below the table top (z = 0)";
  if (p[2] > kMaxPutHeight)
    return at + " is " + format_number(p[2]) + " m above the table top (a thing is put down at most " +
           format_number(kMaxPutHeight) + " m above it)";
  return {};
}

}  // namespace rtamp::world
