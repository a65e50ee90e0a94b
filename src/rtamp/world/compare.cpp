#include "rtamp/world/compare.hpp"

#include <sstream>

#include "rtamp/world/propositions.hpp"

namespace rtamp::world {

namespace {

std::string show(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}
std::string show(const Vec3& v) {
  std::string out = "[";
  out += show(v[0]) + ", " + show(v[1]) + ", " + show(v[2]);
  return out + "]";
}
std::string show(const std::string& s) {
  std::string out;  // (not "'" + s + "'": GCC 12 warns -Wrestrict on that falsely)
  out.reserve(s.size() + 2);
  out += '\'';
  out += s;
  out += '\'';
  return out;
}
std::string show(int v) { return std::to_string(v); }
std::string show(const std::optional<Vec3>& v) { return v ? show(*v) : "none"; }
std::string show(const PropExpr& e) { return to_string(e); }
std::string show(Intervention::Kind k) { return std::to_string(static_cast<int>(k)); }
std::string show(Camera::Mount m) { return to_string(m); }

class Diff {
 public:
  template <class T>
  bool field(const std::string& path, const T& a, const T& b) {
    if (!out.empty()) return false;
    if (a == b) return true;
    out = path + ": " + show(a) + " vs " + show(b);
    return false;
  }
  bool count(const std::string& path, std::size_t a, std::size_t b) {
    if (!out.empty()) return false;
    if (a == b) return true;
    out = path + ": " + std::to_string(a) + " vs " + std::to_string(b) + " entries";
    return false;
  }
  std::string out;
};

std::string idx(const char* list, std::size_t i) { return std::string(list) + "[" + std::to_string(i) + "]"; }

}  // namespace

std::string first_difference(const Scenario& a, const Scenario& b) {
  Diff d;
  d.field("name", a.name, b.name);
  d.field("description", a.description, b.description);
  d.field("robot.model", a.robot.model, b.robot.model);
  d.field("robot.base", a.robot.base, b.robot.base);
  d.field("robot.yaw", a.robot.yaw, b.robot.yaw);
  if (d.count("regions", a.regions.size(), b.regions.size()))
    for (std::size_t i = 0; i < a.regions.size(); ++i) {
      const Region &x = a.regions[i], &y = b.regions[i];
      d.field(idx("regions", i) + ".name", x.name, y.name);
      d.field(idx("regions", i) + ".center", x.center, y.center);
      d.field(idx("regions", i) + ".size", x.size, y.size);
      d.field(idx("regions", i) + ".capacity", x.capacity, y.capacity);
    }
  if (d.count("containers", a.containers.size(), b.containers.size()))
    for (std::size_t i = 0; i < a.containers.size(); ++i) {
      const Container &x = a.containers[i], &y = b.containers[i];
      d.field(idx("containers", i) + ".name", x.name, y.name);
      d.field(idx("containers", i) + ".class", x.cls, y.cls);
      d.field(idx("containers", i) + ".position", x.position, y.position);
      d.field(idx("containers", i) + ".size", x.size, y.size);
      d.field(idx("containers", i) + ".capacity", x.capacity, y.capacity);
    }
  if (d.count("objects", a.objects.size(), b.objects.size()))
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
      const Object &x = a.objects[i], &y = b.objects[i];
      d.field(idx("objects", i) + ".name", x.name, y.name);
      d.field(idx("objects", i) + ".class", x.cls, y.cls);
      d.field(idx("objects", i) + ".position", x.position, y.position);
      d.field(idx("objects", i) + ".size", x.size, y.size);
    }
  if (d.count("propositions", a.propositions.size(), b.propositions.size()))
    for (std::size_t i = 0; i < a.propositions.size(); ++i) {
      const Proposition &x = a.propositions[i], &y = b.propositions[i];
      d.field(idx("propositions", i) + ".name", x.name, y.name);
      d.field(idx("propositions", i) + ".text", x.text, y.text);
      d.field(idx("propositions", i) + ".expr", x.expr, y.expr);
    }
  d.field("task", a.task, b.task);
  if (d.count("operator", a.interventions.size(), b.interventions.size()))
    for (std::size_t i = 0; i < a.interventions.size(); ++i) {
      const Intervention &x = a.interventions[i], &y = b.interventions[i];
      d.field(idx("operator", i) + ".time", x.time, y.time);
      d.field(idx("operator", i) + ".action", x.kind, y.kind);
      d.field(idx("operator", i) + ".subject", x.subject, y.subject);
      d.field(idx("operator", i) + ".class", x.cls, y.cls);
      d.field(idx("operator", i) + ".to", x.location, y.location);
      d.field(idx("operator", i) + ".position", x.position, y.position);
    }
  if (d.count("new tasks", a.task_changes.size(), b.task_changes.size()))
    for (std::size_t i = 0; i < a.task_changes.size(); ++i) {
      const TaskChange &x = a.task_changes[i], &y = b.task_changes[i];
      d.field(idx("new tasks", i) + ".time", x.time, y.time);
      d.field(idx("new tasks", i) + ".task", x.task, y.task);
      if (d.count(idx("new tasks", i) + ".propositions", x.propositions.size(), y.propositions.size()))
        for (std::size_t k = 0; k < x.propositions.size(); ++k) {
          d.field(idx("new tasks", i) + ".propositions." + x.propositions[k].name, x.propositions[k].text,
                  y.propositions[k].text);
        }
    }
  if (d.count("colours", a.colours.size(), b.colours.size()))
    for (std::size_t i = 0; i < a.colours.size(); ++i) {
      d.field(idx("colours", i) + ".class", a.colours[i].cls, b.colours[i].cls);
      d.field(idx("colours", i) + ".rgb", a.colours[i].rgb, b.colours[i].rgb);
    }
  if (d.count("cameras", a.cameras.size(), b.cameras.size()))
    for (std::size_t i = 0; i < a.cameras.size(); ++i) {
      const Camera &x = a.cameras[i], &y = b.cameras[i];
      const std::string c = idx("cameras", i);
      d.field(c + ".name", x.name, y.name);
      d.field(c + ".mount", x.mount, y.mount);
      d.field(c + ".position", x.position, y.position);
      d.field(c + ".look_at", x.look_at, y.look_at);
      d.field(c + ".resolution.width", x.width, y.width);
      d.field(c + ".resolution.height", x.height, y.height);
      d.field(c + ".fov", x.fovy, y.fovy);
      d.field(c + ".range.near", x.near, y.near);
      d.field(c + ".range.far", x.far, y.far);
      d.field(c + ".rate", x.rate, y.rate);
      d.field(c + ".noise.a", x.noise.a, y.noise.a);
      d.field(c + ".noise.b", x.noise.b, y.noise.b);
      d.field(c + ".noise.quantum_mm", x.noise.quantum_mm, y.noise.quantum_mm);
      d.field(c + ".noise.edge_dropout", x.noise.edge_dropout, y.noise.edge_dropout);
    }
  return d.out;
}

bool equivalent(const Scenario& a, const Scenario& b) { return first_difference(a, b).empty(); }

}  // namespace rtamp::world
