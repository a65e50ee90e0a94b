#include "rtamp/world/camera.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

}  // namespace

Camera default_camera(Camera::Mount mount) {
  Camera c;
  c.mount = mount;
  c.fovy = 60;
  if (mount == Camera::Mount::Wrist) {
    c.position = {0.065, 0, 0.02};
    c.width = 424, c.height = 240, c.fovy = 58, c.near = 0.3;
  }
  return c;
}

std::vector<Camera> default_cameras(const Scenario& s) {
  // What must be seen: the regions, containers and objects (x, y), with a margin.
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  auto cover = [&](const Vec3& c, double hx, double hy) {
    xmin = std::min(xmin, c[0] - hx), xmax = std::max(xmax, c[0] + hx);
    ymin = std::min(ymin, c[1] - hy), ymax = std::max(ymax, c[1] + hy);
  };
  for (const Region& r : s.regions) cover(r.center, r.size[0] / 2, r.size[1] / 2);
  for (const Container& c : s.containers) cover(c.position, c.size[0] / 2, c.size[1] / 2);
  for (const Object& o : s.objects) cover(o.position, o.size[0] / 2, o.size[1] / 2);
  const double margin = 0.08;
  const double cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
  // Set back from the robot's base (d: base -> centre) so the arm at home hides
  // little; the image's x runs along p, perpendicular to d.
  double dx = cx - s.robot.base[0], dy = cy - s.robot.base[1];
  const double dn = std::hypot(dx, dy);
  if (dn < 1e-6) dx = std::cos(s.robot.yaw), dy = std::sin(s.robot.yaw);
  else dx /= dn, dy /= dn;
  double along_d = 0, along_p = 0;  // half-extents of the box along d and p
  for (double x : {xmin, xmax})
    for (double y : {ymin, ymax}) {
      along_d = std::max(along_d, std::abs((x - cx) * dx + (y - cy) * dy));
      along_p = std::max(along_p, std::abs(-(x - cx) * dy + (y - cy) * dx));
    }
  Camera overhead = default_camera(Camera::Mount::Fixed);
  overhead.name = "overhead";
  const double tv = std::tan(overhead.fovy / 2 * kPi / 180), th = tv * overhead.width / overhead.height;
  const double height = 1.15 * std::max((along_p + margin) / th, (along_d + margin) / tv) + 0.05;
  const double setback = 0.15 * height;
  overhead.look_at = {cx, cy, 0};
  overhead.position = {cx + setback * dx, cy + setback * dy, height};
  overhead.far = std::max(3.0, 2 * height);

  Camera wrist = default_camera(Camera::Mount::Wrist);
  wrist.name = "wrist";
  return {overhead, wrist};
}

std::vector<Camera> cameras_of(const Scenario& s) { return s.cameras.empty() ? default_cameras(s) : s.cameras; }

const Camera& find_camera(const std::vector<Camera>& cameras, const std::string& name, const SourceLocation& where) {
  std::string names;
  for (const Camera& c : cameras) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw Error("unknown camera '" + name + "' (cameras: " + names + ")", where);
}

const Camera& primary_camera(const std::vector<Camera>& cameras) {
  for (const Camera& c : cameras)
    if (c.mount == Camera::Mount::Fixed) return c;
  return cameras.at(0);
}

double horizontal_fov(const Camera& c) {
  const double t = std::tan(c.fovy / 2 * kPi / 180) * c.width / c.height;
  return 2 * std::atan(t) * 180 / kPi;
}

std::array<Vec3, 3> fixed_camera_axes(const Camera& c) {
  const Vec3 z = unit(sub(c.look_at, c.position));
  // Image "up" is the world's z, or its x when looking straight up or down.
  const Vec3 up = std::abs(z[2]) > 0.999 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
  const Vec3 x = unit(cross(z, up));
  const Vec3 y = cross(z, x);
  return {x, y, z};
}

bool fixed_camera_sees(const Camera& c, const Vec3& p) {
  const auto axes = fixed_camera_axes(c);
  const Vec3 v = sub(p, c.position);
  const double x = dot(axes[0], v), y = dot(axes[1], v), z = dot(axes[2], v);
  if (!(z >= c.near && z <= c.far)) return false;
  const double ty = std::tan(c.fovy / 2 * kPi / 180), tx = ty * c.width / c.height;
  return std::abs(x / z) <= tx && std::abs(y / z) <= ty;
}

const char* to_string(Camera::Mount m) { return m == Camera::Mount::Wrist ? "wrist" : "fixed"; }

}  // namespace rtamp::world
