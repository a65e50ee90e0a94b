#include "rtamp/world/validate.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "rtamp/world/fit.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/intervention_rules.hpp"
#include "rtamp/world/table.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::world {

namespace {

std::string quote(const std::string& s) {
  std::string out;  // (not "'" + s + "'": GCC 12 warns -Wrestrict on that falsely)
  out.reserve(s.size() + 2);
  out += '\'';
  out += s;
  out += '\'';
  return out;
}

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string fmt(const Vec3& v) { return "[" + fmt(v[0]) + ", " + fmt(v[1]) + ", " + fmt(v[2]) + "]"; }

class Validator {
 public:
  Validator(const Scenario& s, const detail::FieldLocator& locate) : s_(s), locate_(locate) {}

  void run() {
    if (s_.name.empty()) fail(at({}, "name"), "the scenario has no name");
    check_robot();
    check_regions();
    check_containers();
    check_objects();
    check_unique_names();
    check_classes();
    check_geometry();
    check_propositions();
    if (std::all_of(s_.task.begin(), s_.task.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }))
      fail(s_.task_where, "the task is empty (write an LTL formula over the propositions, e.g. \"F G all_in_r2\")");
    check_interventions();
    check_cameras();
    check_colours();
  }

 private:
  [[noreturn]] void fail(const SourceLocation& where, const std::string& what, const std::string& detail = {}) const {
    throw Error(what, where, detail);
  }

  SourceLocation at(const SourceLocation& element, std::string_view field) const {
    if (locate_) return locate_(element, field);
    return element;
  }

  void check_name(const std::string& name, const char* kind, const SourceLocation& where) const {
    check_new_name(name, kind, at(where, "name"));
  }

  void check_class(const std::string& cls, const std::string& owner, const SourceLocation& where) const {
    check_class_name(cls, owner, at(where, "class"));
  }

  void check_vec(const Vec3& v, const std::string& owner, const char* field, const SourceLocation& where) const {
    std::string shown(field);
    if (const auto dot = shown.rfind('.'); dot != std::string::npos) shown = shown.substr(dot + 1);
    for (double x : v)
      if (!std::isfinite(x) || std::abs(x) > kMaxCoordinate)
        fail(at(where, field), owner + ": " + shown + " " + fmt(v) + " is out of range (coordinates are finite, within ±1000 m)");
  }

  void check_size(const Vec3& size, int dims, const std::string& owner, const SourceLocation& where) const {
    for (int i = 0; i < dims; ++i)
      if (!(size[i] > 0) || !(size[i] <= kMaxSize))
        fail(at(where, "size"), owner + ": size " + fmt(size) + " must be positive (and at most 100 m) in x, y" +
                                    (dims == 3 ? ", z" : ""));
    if (dims == 2 && (!std::isfinite(size[2]) || size[2] < 0 || size[2] > kMaxSize))
      fail(at(where, "size"), owner + ": size z " + fmt(size[2]) + " must be between 0 and 100 m");
  }

  void check_capacity(int capacity, const std::string& owner, const SourceLocation& where) const {
    if (capacity < 1) fail(at(where, "capacity"), owner + ": capacity must be at least 1 (got " + std::to_string(capacity) + ")");
  }

  void check_robot() const {
    if (s_.robot.model != "ur5")
      fail(at({}, "robot.model"), "unknown robot model " + quote(s_.robot.model) + " (rtamp knows: ur5)");
    check_vec(s_.robot.base, "robot", "robot.base", {});
    if (!(std::abs(s_.robot.yaw) <= kMaxYaw))
      fail(at({}, "robot.yaw"), "robot: yaw " + fmt(s_.robot.yaw) + " is out of range (radians within ±2π)");
  }

  void check_regions() const {
    if (s_.regions.empty()) fail(at({}, "regions"), "the scenario has no regions (at least one is needed)");
    for (const Region& r : s_.regions) {
      check_name(r.name, "region", r.where);
      const std::string owner = "region " + quote(r.name);
      check_vec(r.center, owner, "center", r.where);
      if (!(std::abs(r.center[2]) <= kUnderTableTolerance))
        fail(at(r.where, "center"), owner + ": centre z = " + fmt(r.center[2]) +
                                        " is not on the table top (z = 0; a region is a patch of the table)");
      check_size(r.size, 2, owner, r.where);
      check_capacity(r.capacity, owner, r.where);
    }
  }

  void check_containers() const {
    for (const Container& c : s_.containers) {
      check_name(c.name, "container", c.where);
      const std::string owner = "container " + quote(c.name);
      check_class(c.cls, owner, c.where);
      check_vec(c.position, owner, "position", c.where);
      check_size(c.size, 3, owner, c.where);
      check_capacity(c.capacity, owner, c.where);
    }
  }

  void check_objects() const {
    for (const Object& o : s_.objects) {
      check_name(o.name, "object", o.where);
      const std::string owner = "object " + quote(o.name);
      check_class(o.cls, owner, o.where);
      check_vec(o.position, owner, "position", o.where);
      check_size(o.size, 3, owner, o.where);
    }
  }

  void check_cameras() const {
    std::map<std::string, SourceLocation> seen;
    for (const Camera& c : s_.cameras) {
      check_name(c.name, "camera", c.where);
      const std::string owner = "camera " + quote(c.name);
      if (!seen.emplace(c.name, c.where).second) fail(at(c.where, "name"), "duplicate camera name " + quote(c.name));
      check_vec(c.position, owner, "position", c.where);
      for (int v : {c.width, c.height})
        if (v < kMinCameraPixels || v > kMaxCameraPixels)
          fail(at(c.where, "resolution"), owner + ": resolution " + std::to_string(c.width) + "x" +
                                              std::to_string(c.height) + " is out of range (16 to 4096 pixels a side)");
      if (!(c.fovy > 0 && c.fovy < 180))
        fail(at(c.where, "fov"), owner + ": field of view " + fmt(c.fovy) + " is outside (0, 180) degrees");
      if (!(c.near > 0 && c.near < c.far && c.far <= kMaxCameraRange))
        fail(at(c.where, "range"), owner + ": range [" + fmt(c.near) + ", " + fmt(c.far) +
                                       "] must be near > 0, far > near, far at most 100 m");
      if (!(c.rate > 0 && c.rate <= kMaxCameraRate))
        fail(at(c.where, "rate"), owner + ": rate " + fmt(c.rate) + " Hz is out of range (above 0, at most 1000)");
      const DepthNoise& z = c.noise;
      if (!(z.a <= 1 && z.b <= 1 && z.quantum_mm <= 100 && z.edge_dropout <= 1))
        fail(at(c.where, "noise"), owner + ": noise out of range (a, b at most 1, quantum_mm at most 100, "
                                           "edge_dropout at most 1)");
      if (c.mount == Camera::Mount::Wrist) {
        if (!(std::abs(c.position[0]) <= 0.5 && std::abs(c.position[1]) <= 0.5 && std::abs(c.position[2]) <= 0.5))
          fail(at(c.where, "position"), owner + ": a wrist camera's position " + fmt(c.position) +
                                            " (in the flange frame) must be within 0.5 m of the flange");
        continue;
      }
      check_vec(c.look_at, owner, "look_at", c.where);
      if (!(c.position[2] > 0))
        fail(at(c.where, "position"), owner + ": position " + fmt(c.position) +
                                          " is inside or below the table (a fixed camera must be above z = 0)");
      if (c.position == c.look_at) fail(at(c.where, "look_at"), owner + ": look_at is the camera's own position");
      const bool sees = std::any_of(s_.regions.begin(), s_.regions.end(),
                                    [&](const Region& r) { return fixed_camera_sees(c, r.center); });
      if (!sees)
        fail(at(c.where, "look_at"), owner + " sees no region (no region's centre is inside its view within its range)");
    }
  }

  void check_unique_names() {
    auto add = [&](const std::string& name, const char* kind, const SourceLocation& where) {
      auto [it, inserted] = defined_.emplace(name, std::make_pair(std::string(kind), where));
      if (!inserted) {
        const std::string prev = format_location(it->second.second);
        fail(at(where, "name"), "duplicate name " + quote(name) + ": already used by " + it->second.first +
                                    (prev.empty() ? "" : " at " + prev.substr(0, prev.size() - 2)));
      }
    };
    for (const Region& r : s_.regions) add(r.name, "a region", r.where);
    for (const Container& c : s_.containers) add(c.name, "a container", c.where);
    for (const Object& o : s_.objects) add(o.name, "an object", o.where);
  }

  void check_classes() {
    for (const Object& o : s_.objects) object_classes_.insert(o.cls);
    for (const Container& c : s_.containers) {
      container_classes_.insert(c.cls);
      if (object_classes_.count(c.cls))
        fail(at(c.where, "class"), "container " + quote(c.name) + ": class " + quote(c.cls) +
                                       " is also the class of objects (a class names either objects or containers)");
    }
  }

  void check_geometry() {
    for (std::size_t i = 0; i < s_.regions.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (footprint(s_.regions[i]).overlaps(footprint(s_.regions[j])))
          fail(s_.regions[i].where, "region " + quote(s_.regions[i].name) + " overlaps region " + quote(s_.regions[j].name) +
                                        " (regions must be disjoint)");
    for (std::size_t i = 0; i < s_.containers.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (footprint(s_.containers[i]).overlaps(footprint(s_.containers[j])))
          fail(s_.containers[i].where, "container " + quote(s_.containers[i].name) + " overlaps container " +
                                           quote(s_.containers[j].name));
    const Geometry g(s_);
    std::map<std::string, int> load;
    for (const Container& c : s_.containers) {
      const std::string loc = g.locate_region(c.position);
      if (loc == kNoLocation)
        fail(at(c.where, "position"), "container " + quote(c.name) + " at " + fmt(c.position) +
                                          " is not in any region (a container must stand in a region)");
      check_fits(c.size, "container " + quote(c.name), loc, c.where);
      check_rests(c.position, "container " + quote(c.name), loc, g, c.where);
      ++load[loc];
    }
    for (const Object& o : s_.objects) {
      const std::string loc = g.locate(o.position);
      if (loc == kNoLocation)
        fail(at(o.where, "position"), "object " + quote(o.name) + " at " + fmt(o.position) +
                                          " is outside every region and container");
      check_fits(o.size, "object " + quote(o.name), loc, o.where);
      check_rests(o.position, "object " + quote(o.name), loc, g, o.where);
      ++load[loc];
    }
    for (const Region& r : s_.regions)
      if (load[r.name] > r.capacity)
        fail(at(r.where, "capacity"), "region " + quote(r.name) + " initially holds " + std::to_string(load[r.name]) +
                                          " things but its capacity is " + std::to_string(r.capacity));
    for (const Container& c : s_.containers)
      if (load[c.name] > c.capacity)
        fail(at(c.where, "capacity"), "container " + quote(c.name) + " initially holds " + std::to_string(load[c.name]) +
                                          " objects but its capacity is " + std::to_string(c.capacity));
  }

  // The thing starts resting on its location's surface (geometry.hpp), not
  // floating above it; locate() already refuses a point below it.
  void check_rests(const Vec3& p, const std::string& owner, const std::string& loc, const Geometry& g,
                   const SourceLocation& where) const {
    const double surface = g.surface_z(loc).value_or(0);
    if (p[2] - surface > kBelowTolerance)
      fail(at(where, "position"), owner + " at " + fmt(p) + " floats " + fmt(p[2] - surface) + " m above the surface of " +
                                      quote(loc) + " (z = " + fmt(surface) + "; things start resting on their location, within " +
                                      fmt(kBelowTolerance) + " m)");
  }

  // The thing's footprint fits the location it starts in (fit.hpp: no
  // rotation; a container's floor inside its rims), as the planner requires.
  void check_fits(const Vec3& size, const std::string& owner, const std::string& loc, const SourceLocation& where) const {
    const FitRules rules;
    if (const Region* r = s_.find_region(loc)) {
      const Extent u = usable_extent(*r);
      if (!fits(size, u))
        fail(at(where, "size"), owner + " (" + fmt(size[0]) + " x " + fmt(size[1]) + " m) does not fit in region " +
                                    quote(loc) + " (" + fmt(u.x) + " x " + fmt(u.y) +
                                    " m; things keep their orientation)");
    } else if (const Container* c = s_.find_container(loc)) {
      const Extent u = usable_extent(*c, rules);
      if (!fits(size, u))
        fail(at(where, "size"), owner + " (" + fmt(size[0]) + " x " + fmt(size[1]) + " m) does not fit in container " +
                                    quote(loc) + " (its floor inside the rims is " + fmt(u.x) + " x " + fmt(u.y) +
                                    " m; things keep their orientation)");
    }
  }

  void check_propositions() const {
    std::set<std::string> seen;
    const Vocabulary vocabulary(s_);
    for (const Proposition& p : s_.propositions) {
      const SourceLocation name_loc = at(p.where, "name");
      if (!is_valid_proposition_name(p.name))
        fail(name_loc, "proposition name " + quote(p.name) +
                           " is not a valid atom (lower-case letter or '_' first, then letters, digits, '_'; not true/false)");
      if (!seen.insert(p.name).second) fail(name_loc, "duplicate proposition " + quote(p.name));
      if (defined_.count(p.name))
        fail(name_loc, "proposition " + quote(p.name) + " has the name of " + defined_.at(p.name).first);
      check_expression_names(p.expr, p.text, p.where, vocabulary, "proposition " + quote(p.name) + ": ", p.layout);
    }
  }

  void check_interventions() const {
    InterventionWorld w;  // the world as the script has made it so far
    for (const Object& o : s_.objects) {
      w.objects[o.name] = o.cls;
      w.ever.emplace(o.name, false);
      w.classes.emplace(o.cls, false);
    }
    for (const Container& c : s_.containers) {
      w.containers[c.name] = c.cls;
      w.ever.emplace(c.name, true);
      w.classes.emplace(c.cls, true);
    }
    // A name or class the script adds later is of its kind from the start.
    for (const Intervention& iv : s_.interventions)
      if (iv.kind == Intervention::Kind::Add || iv.kind == Intervention::Kind::AddContainer) {
        const bool cont = iv.kind == Intervention::Kind::AddContainer;
        if (!iv.cls.empty()) w.classes.emplace(iv.cls, cont);
      }
    double prev_time = 0;
    for (const Intervention& iv : s_.interventions) {
      const std::string owner = std::string("operator action '") +
                                intervention_kind_name(iv.kind, InterventionSyntax::Scenario) + "' at t=" +
                                fmt(iv.time) + ": ";
      if (!std::isfinite(iv.time) || iv.time < 0)
        fail(at(iv.where, "time"), owner + "time must be a finite number of seconds >= 0");
      if (iv.time < prev_time)
        fail(at(iv.where, "time"), owner + "operator actions must be sorted by time (previous one at t=" + fmt(prev_time) + ")");
      prev_time = iv.time;
      if (iv.position) check_vec(*iv.position, owner.substr(0, owner.size() - 2), "position", iv.where);
      check_intervention(iv, s_, w, InterventionSyntax::Scenario, owner,
                         [&](std::string_view field) { return field.empty() ? iv.where : at(iv.where, field); });
      note_intervention(iv, w);
    }
  }

  // A colour is for a class the scenario has (its things, what the operator adds, or the
  // default classes block and tray): a listed class nothing has is a typo.
  void check_colours() const {
    std::set<std::string> known = {"block", "tray"};
    known.insert(object_classes_.begin(), object_classes_.end());
    known.insert(container_classes_.begin(), container_classes_.end());
    for (const Intervention& iv : s_.interventions)
      if (!iv.cls.empty()) known.insert(iv.cls);
    for (const ClassColour& c : s_.colours) {
      for (double x : c.rgb)
        if (!(x >= 0 && x <= 1))
          fail(c.where, "colours: " + quote(c.cls) + ": " + fmt(c.rgb) + " has a channel outside [0, 1]");
      if (!known.count(c.cls))
        fail(c.where, "colours: unknown class " + quote(c.cls) +
                          suggestion(c.cls, std::vector<std::string>(known.begin(), known.end())));
    }
  }

  const Scenario& s_;
  const detail::FieldLocator& locate_;
  std::map<std::string, std::pair<std::string, SourceLocation>> defined_;  // name -> (kind, where)
  std::set<std::string> object_classes_, container_classes_;
};

}  // namespace

void validate(const Scenario& s) {
  const detail::FieldLocator none;
  Validator(s, none).run();
}

void detail::validate(const Scenario& s, const FieldLocator& locate_field) { Validator(s, locate_field).run(); }

}  // namespace rtamp::world
