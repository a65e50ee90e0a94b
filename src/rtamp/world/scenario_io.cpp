#include "rtamp/world/scenario_io.hpp"

// yaml-cpp 0.7's node/impl.h trips GCC 12's -Wdangling-pointer (a false positive in its inlined code).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdangling-pointer"
#endif
#include <yaml-cpp/yaml.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/suggest.hpp"
#include "rtamp/world/validate.hpp"
#include "rtamp/util/text_file.hpp"

namespace rtamp::world {

namespace {

// ---------------------------------------------------------------- reading

bool valid_utf8(std::string_view s) {
  std::size_t i = 0;
  const std::size_t n = s.size();
  auto cont = [&](std::size_t k) { return k < n && (static_cast<unsigned char>(s[k]) & 0xC0) == 0x80; };
  while (i < n) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      ++i;
    } else if (c >= 0xC2 && c <= 0xDF) {
      if (!cont(i + 1)) return false;
      i += 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      if (!cont(i + 1) || !cont(i + 2)) return false;
      const auto c1 = static_cast<unsigned char>(s[i + 1]);
      if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 >= 0xA0)) return false;  // overlong, surrogates
      i += 3;
    } else if (c >= 0xF0 && c <= 0xF4) {
      if (!cont(i + 1) || !cont(i + 2) || !cont(i + 3)) return false;
      const auto c1 = static_cast<unsigned char>(s[i + 1]);
      if ((c == 0xF0 && c1 < 0x90) || (c == 0xF4 && c1 >= 0x90)) return false;
      i += 4;
    } else {
      return false;
    }
  }
  return true;
}

const std::vector<std::string> kRootKeys = {"name",    "description", "robot",        "regions", "containers",
                                            "objects", "propositions", "task",        "operator",
                                            "cameras", "colours"};
const std::vector<std::string> kRegionKeys = {"name", "center", "size", "capacity"};
const std::vector<std::string> kContainerKeys = {"name", "class", "position", "size", "capacity"};
const std::vector<std::string> kObjectKeys = {"name", "class", "position", "size"};
const std::vector<std::string> kCameraKeys = {"name", "mount", "position", "look_at", "resolution",
                                              "fov",  "range", "rate",     "noise"};
const std::vector<std::string> kNoiseKeys = {"a", "b", "quantum_mm", "edge_dropout"};
const std::vector<std::string> kRobotKeys = {"model", "base", "yaw"};

struct ActionSpec {
  const char* name;
  Intervention::Kind kind;
  std::vector<std::string> keys;  // besides time and action
};

constexpr const char* kNewTask = "new_task";  // the operator action that gives a new task

const std::vector<ActionSpec>& action_specs() {
  static const std::vector<ActionSpec> specs = {
      {"relocate", Intervention::Kind::Relocate, {"object", "container", "to", "position"}},
      {"add", Intervention::Kind::Add, {"object", "class", "to", "position"}},
      {"remove", Intervention::Kind::Remove, {"object"}},
      {"add_container", Intervention::Kind::AddContainer, {"container", "class", "to", "position"}},
      {"remove_container", Intervention::Kind::RemoveContainer, {"container"}},
      {"take_from_gripper", Intervention::Kind::TakeFromGripper, {"to", "position"}},
  };
  return specs;
}

class Reader {
 public:
  Reader(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  Scenario read() {
    if (text_.size() > kMaxScenarioBytes)
      throw Error("scenario file is too large (" + std::to_string(text_.size()) + " bytes; at most 16 MiB)",
                  SourceLocation{source_, 0, 0});
    // One document only. (Not YAML::LoadAll: yaml-cpp 0.7 loops forever on
    // some malformed inputs there, e.g. "!(a,)"; found by fuzzing.)
    check_single_document();
    YAML::Node root;
    try {
      root = YAML::Load(std::string(text_));
    } catch (const YAML::Exception& e) {
      throw Error("invalid YAML: " + e.msg, mark_loc(e.mark));
    }
    if (root.IsNull()) throw Error("the scenario file is empty", SourceLocation{source_, 1, 1});
    if (!root.IsMap())
      throw Error("a scenario must be a mapping of keys (name:, regions:, objects:, task:, ...)", loc(root));

    Scenario s;
    s.source = source_;
    check_keys(root, kRootKeys, "scenario");
    s.name = required_string(root, "name", "scenario", {});
    if (auto d = optional(root, "description")) s.description = text_value(*d, "description");
    if (auto r = optional(root, "robot")) read_robot(*r, s.robot);
    remember({}, "regions", required(root, "regions", "scenario", {}));
    for_each_item(required(root, "regions", "scenario", {}), "regions", [&](const YAML::Node& n) {
      s.regions.push_back(read_region(n));
    });
    if (auto c = optional(root, "containers"))
      for_each_item(*c, "containers", [&](const YAML::Node& n) { s.containers.push_back(read_container(n)); });
    for_each_item(required(root, "objects", "scenario", {}), "objects", [&](const YAML::Node& n) {
      s.objects.push_back(read_object(n));
    });
    if (auto p = optional(root, "propositions")) read_propositions(*p, s.propositions);
    {
      const YAML::Node t = required(root, "task", "scenario", {});
      s.task = text_value(t, "task");
      s.task_where = text_start(t);
      s.task_layout = text_layout(t);
    }
    if (auto o = optional(root, "operator"))
      for_each_item(*o, "operator", [&](const YAML::Node& n) {
        if (is_new_task(n)) s.task_changes.push_back(read_task_change(n));
        else s.interventions.push_back(read_intervention(n));
      });
    if (auto c = optional(root, "cameras"))
      for_each_item(*c, "cameras", [&](const YAML::Node& n) { s.cameras.push_back(read_camera(n)); });
    if (auto c = optional(root, "colours")) read_colours(*c, s.colours);
    std::stable_sort(s.interventions.begin(), s.interventions.end(),
                     [](const Intervention& a, const Intervention& b) { return a.time < b.time; });
    std::stable_sort(s.task_changes.begin(), s.task_changes.end(),
                     [](const TaskChange& a, const TaskChange& b) { return a.time < b.time; });

    detail::validate(s, [this](const SourceLocation& element, std::string_view field) {
      auto it = fields_.find(std::make_tuple(element.line, element.column, std::string(field)));
      if (it != fields_.end()) return it->second;
      if (element.line == 0 && element.file.empty()) return SourceLocation{source_, 0, 0};
      return element;
    });
    return s;
  }

 private:
  // A document marker at column 1 ("---", or content after "...") once the
  // first document has content starts a second document. (Inside a document,
  // no scalar's text can start a line with a marker.)
  void check_single_document() const {
    bool content = false, ended = false;
    int line = 0;
    std::size_t start = 0;
    while (start <= text_.size()) {
      std::size_t end = text_.find('\n', start);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view l = text_.substr(start, end - start);
      start = end + 1;
      ++line;
      if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
      const bool marker = (l.substr(0, 3) == "---" || l.substr(0, 3) == "...") &&
                          (l.size() == 3 || l[3] == ' ' || l[3] == '\t');
      const std::string_view rest = marker ? l.substr(3) : l;
      const auto first = rest.find_first_not_of(" \t");
      const bool text = first != std::string_view::npos && rest[first] != '#';
      const bool second = marker ? (l[0] == '-' && (content || ended)) : (text && ended);
      if (second) throw Error("more than one YAML document (only one scenario per file)", SourceLocation{source_, line, 1});
      if (marker && l[0] == '.') {
        ended = ended || content;
      } else if (text && !(l[0] == '%' && !content)) {
        content = true;
      }
    }
  }

  // --- locations

  SourceLocation mark_loc(const YAML::Mark& m) const {
    if (m.is_null() || m.line < 0) return SourceLocation{source_, 0, 0};
    return SourceLocation{source_, m.line + 1, m.column + 1};
  }
  SourceLocation loc(const YAML::Node& n) const { return mark_loc(n.Mark()); }

  bool is_quoted(const YAML::Node& n) const {
    const YAML::Mark m = n.Mark();
    if (m.is_null() || m.pos < 0 || static_cast<std::size_t>(m.pos) >= text_.size()) return false;
    const char c = text_[static_cast<std::size_t>(m.pos)];
    return n.IsScalar() && (c == '"' || c == '\'');
  }

  // Where a scalar's text starts: after the opening quote of a quoted scalar;
  // on its first line of content for a block scalar (| or >).
  SourceLocation text_start(const YAML::Node& n) const {
    SourceLocation l = loc(n);
    const YAML::Mark m = n.Mark();
    if (!n.IsScalar() || m.is_null() || m.pos < 0 || static_cast<std::size_t>(m.pos) >= text_.size()) return l;
    const auto pos = static_cast<std::size_t>(m.pos);
    const char c = text_[pos];
    if (c == '"' || c == '\'') {
      ++l.column;
    } else if (c == '|' || c == '>') {
      std::size_t nl = text_.find('\n', pos);
      int line = l.line;
      while (nl != std::string_view::npos) {
        const std::size_t start = nl + 1;
        ++line;
        nl = text_.find('\n', start);
        const std::string_view content = text_.substr(start, (nl == std::string_view::npos ? text_.size() : nl) - start);
        const std::size_t first = content.find_first_not_of(" \r");
        if (first != std::string_view::npos) return SourceLocation{source_, line, static_cast<int>(first) + 1};
      }
    }
    return l;
  }

  // Where a block scalar's bytes lie in the file (util/text_layout.hpp); empty
  // for other scalars, whose text lies as written from text_start().
  TextLayout text_layout(const YAML::Node& n) const {
    const YAML::Mark m = n.Mark();
    if (!n.IsScalar() || m.is_null() || m.pos < 0 || static_cast<std::size_t>(m.pos) >= text_.size()) return {};
    const auto pos = static_cast<std::size_t>(m.pos);
    if (text_[pos] != '|' && text_[pos] != '>') return {};
    return block_scalar_layout(text_, pos, m.line + 1, n.Scalar());
  }

  void remember(const SourceLocation& element, const std::string& field, const YAML::Node& value) {
    fields_[std::make_tuple(element.line, element.column, field)] = loc(value);
  }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& what) const { throw Error(what, loc(n)); }

  static std::string describe(const YAML::Node& n) {
    switch (n.Type()) {
      case YAML::NodeType::Null:
        return "nothing";
      case YAML::NodeType::Scalar:
        return quoted(n.Scalar().size() > 40 ? n.Scalar().substr(0, 40) + "..." : n.Scalar());
      case YAML::NodeType::Sequence:
        return "a list";
      case YAML::NodeType::Map:
        return "a mapping";
      default:
        return "nothing";
    }
  }

  // --- structure

  // Rejects unknown and duplicate keys; keys must be plain scalars.
  void check_keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what) const {
    std::set<std::string> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node key = it->first;  // a copy: it->first lives in a temporary
      if (!key.IsScalar()) fail(key, "keys of " + what + " must be words, found " + describe(key));
      const std::string& k = key.Scalar();
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
        fail(key, "unknown key " + quoted(k) + " in " + what + suggestion(k, allowed));
      if (!seen.insert(k).second) fail(key, "duplicate key " + quoted(k) + " in " + what);
    }
  }

  std::optional<YAML::Node> optional(const YAML::Node& map, const char* key) const {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node k = it->first, v = it->second;  // copies: it-> yields a temporary
      if (k.IsScalar() && k.Scalar() == key) {
        if (v.IsNull()) return std::nullopt;
        return v;
      }
    }
    return std::nullopt;
  }

  YAML::Node required(const YAML::Node& map, const char* key, const std::string& what, const SourceLocation&) const {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node k = it->first, v = it->second;  // copies: it-> yields a temporary
      if (k.IsScalar() && k.Scalar() == key) {
        if (v.IsNull()) fail(k, std::string("'") + key + "' of " + what + " has no value");
        return v;
      }
    }
    fail(map, what + " is missing the required key '" + key + "'");
  }

  template <class F>
  void for_each_item(const YAML::Node& seq, const std::string& key, F&& f) const {
    if (!seq.IsSequence()) fail(seq, "'" + key + "' must be a list, found " + describe(seq));
    for (const YAML::Node& item : seq) f(item);
  }

  // --- scalars

  std::string text_value(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be text, found " + describe(n));
    const std::string& v = n.Scalar();
    if (!valid_utf8(v)) fail(n, what + " is not valid UTF-8");
    return v;
  }

  std::string required_string(const YAML::Node& map, const char* key, const std::string& what,
                               const SourceLocation& element) {
    const YAML::Node v = required(map, key, what, element);
    remember(element, key, v);
    return text_value(v, what + ": " + key);
  }

  std::string word(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be a name, found " + describe(n));
    return text_value(n, what);
  }

  double number(const YAML::Node& n, const std::string& what) const {
    if (n.IsScalar() && (is_quoted(n) || n.Tag() == "!"))
      fail(n, what + " must be a number, found the quoted string " + describe(n) + " (write it without quotes)");
    if (!n.IsScalar()) fail(n, what + " must be a number, found " + describe(n));
    const std::string& v = n.Scalar();
    const char* first = v.data();
    const char* last = v.data() + v.size();
    if (first != last && *first == '+') ++first;
    double out = 0;
    auto [ptr, ec] = std::from_chars(first, last, out);
    if (ec != std::errc() || ptr != last || first == last) fail(n, what + " must be a number, found " + describe(n));
    if (!std::isfinite(out)) fail(n, what + " must be a finite number, found " + describe(n));
    return out;
  }

  int integer(const YAML::Node& n, const std::string& what) const {
    if (n.IsScalar() && (is_quoted(n) || n.Tag() == "!"))
      fail(n, what + " must be an integer, found the quoted string " + describe(n) + " (write it without quotes)");
    if (!n.IsScalar()) fail(n, what + " must be an integer, found " + describe(n));
    const std::string& v = n.Scalar();
    const char* first = v.data();
    const char* last = v.data() + v.size();
    if (first != last && *first == '+') ++first;
    int out = 0;
    auto [ptr, ec] = std::from_chars(first, last, out);
    if (ec == std::errc::result_out_of_range) fail(n, what + " is out of range: " + describe(n));
    if (ec != std::errc() || ptr != last || first == last) fail(n, what + " must be an integer, found " + describe(n));
    return out;
  }

  // [x, y] or [x, y, z]; `dims_min` 2 or 3. A missing z is `z_default`.
  Vec3 vec(const YAML::Node& n, const std::string& what, int dims_min, double z_default = 0) const {
    const char* shape = dims_min == 3 ? "[x, y, z]" : "[x, y] or [x, y, z]";
    if (!n.IsSequence() || n.size() < static_cast<std::size_t>(dims_min) || n.size() > 3)
      fail(n, what + " must be a list " + shape + ", found " +
                  (n.IsSequence() ? "a list of " + std::to_string(n.size()) + " numbers" : describe(n)));
    Vec3 v{0, 0, z_default};
    for (std::size_t i = 0; i < n.size(); ++i) v[i] = number(n[i], what);
    return v;
  }

  // --- sections

  void read_robot(const YAML::Node& n, Robot& robot) {
    if (!n.IsMap()) fail(n, "robot must be a mapping {model: ur5, base: [x, y, z], yaw: radians}, found " + describe(n));
    check_keys(n, kRobotKeys, "robot");
    if (auto m = optional(n, "model")) {
      robot.model = word(*m, "robot model");
      remember({}, "robot.model", *m);
    }
    if (auto b = optional(n, "base")) {
      robot.base = vec(*b, "robot base", 2);
      remember({}, "robot.base", *b);
    }
    if (auto y = optional(n, "yaw")) {
      robot.yaw = number(*y, "robot yaw");
      remember({}, "robot.yaw", *y);
    }
  }

  std::string element_name(const YAML::Node& n, const char* kind, const SourceLocation& where) {
    const YAML::Node v = required(n, "name", kind, where);
    remember(where, "name", v);
    return word(v, std::string(kind) + " name");
  }

  Region read_region(const YAML::Node& n) {
    if (!n.IsMap()) fail(n, "a region must be a mapping {name, center, size, capacity}, found " + describe(n));
    Region r;
    r.where = loc(n);
    check_keys(n, kRegionKeys, "region");
    r.name = element_name(n, "region", r.where);
    const std::string owner = "region " + quoted(r.name);
    const YAML::Node c = required(n, "center", owner, r.where);
    remember(r.where, "center", c);
    r.center = vec(c, owner + ": center", 2);
    const YAML::Node sz = required(n, "size", owner, r.where);
    remember(r.where, "size", sz);
    r.size = vec(sz, owner + ": size", 2);
    if (auto cap = optional(n, "capacity")) {
      remember(r.where, "capacity", *cap);
      r.capacity = integer(*cap, owner + ": capacity");
    }
    return r;
  }

  Container read_container(const YAML::Node& n) {
    if (!n.IsMap())
      fail(n, "a container must be a mapping {name, class, position, size, capacity}, found " + describe(n));
    Container c;
    c.where = loc(n);
    check_keys(n, kContainerKeys, "container");
    c.name = element_name(n, "container", c.where);
    const std::string owner = "container " + quoted(c.name);
    if (auto cls = optional(n, "class")) {
      remember(c.where, "class", *cls);
      c.cls = word(*cls, owner + ": class");
    }
    const YAML::Node p = required(n, "position", owner, c.where);
    remember(c.where, "position", p);
    c.position = vec(p, owner + ": position", 2);
    if (auto sz = optional(n, "size")) {
      remember(c.where, "size", *sz);
      c.size = vec(*sz, owner + ": size", 3);
    }
    if (auto cap = optional(n, "capacity")) {
      remember(c.where, "capacity", *cap);
      c.capacity = integer(*cap, owner + ": capacity");
    }
    return c;
  }

  Object read_object(const YAML::Node& n) {
    if (!n.IsMap()) fail(n, "an object must be a mapping {name, class, position, size}, found " + describe(n));
    Object o;
    o.where = loc(n);
    check_keys(n, kObjectKeys, "object");
    o.name = element_name(n, "object", o.where);
    const std::string owner = "object " + quoted(o.name);
    if (auto cls = optional(n, "class")) {
      remember(o.where, "class", *cls);
      o.cls = word(*cls, owner + ": class");
    }
    const YAML::Node p = required(n, "position", owner, o.where);
    remember(o.where, "position", p);
    o.position = vec(p, owner + ": position", 2);
    if (auto sz = optional(n, "size")) {
      remember(o.where, "size", *sz);
      o.size = vec(*sz, owner + ": size", 3);
    }
    return o;
  }

  Camera read_camera(const YAML::Node& n) {
    if (!n.IsMap())
      fail(n, "a camera must be a mapping {name, mount, position, look_at, resolution, fov, range, rate, noise}, found " +
                  describe(n));
    check_keys(n, kCameraKeys, "camera");
    const SourceLocation where = loc(n);
    const std::string name = element_name(n, "camera", where);
    const std::string owner = "camera " + quoted(name);
    Camera::Mount mount = Camera::Mount::Fixed;
    if (auto m = optional(n, "mount")) {
      remember(where, "mount", *m);
      const std::string text = word(*m, owner + ": mount");
      if (text == "wrist") mount = Camera::Mount::Wrist;
      else if (text != "fixed") fail(*m, owner + ": unknown mount " + quoted(text) + " (fixed or wrist)");
    }
    Camera c = default_camera(mount);
    c.name = name;
    c.where = where;
    if (auto p = optional(n, "position")) {
      remember(c.where, "position", *p);
      c.position = vec(*p, owner + ": position", 3);
    } else if (c.mount == Camera::Mount::Fixed) {
      fail(n, owner + " is missing the required key 'position' (a fixed camera)");
    }
    if (auto l = optional(n, "look_at")) {
      remember(c.where, "look_at", *l);
      if (c.mount == Camera::Mount::Wrist) fail(*l, owner + ": a wrist camera looks along the tool axis (no look_at)");
      c.look_at = vec(*l, owner + ": look_at", 2);
    } else if (c.mount == Camera::Mount::Fixed) {
      fail(n, owner + " is missing the required key 'look_at' (a fixed camera)");
    }
    if (auto r = optional(n, "resolution")) {
      remember(c.where, "resolution", *r);
      if (!r->IsSequence() || r->size() != 2) fail(*r, owner + ": resolution must be a list [width, height]");
      c.width = integer((*r)[0], owner + ": resolution");
      c.height = integer((*r)[1], owner + ": resolution");
    }
    if (auto f = optional(n, "fov")) {
      remember(c.where, "fov", *f);
      c.fovy = number(*f, owner + ": fov");
    }
    if (auto r = optional(n, "range")) {
      remember(c.where, "range", *r);
      if (!r->IsSequence() || r->size() != 2) fail(*r, owner + ": range must be a list [near, far] (m)");
      c.near = number((*r)[0], owner + ": range");
      c.far = number((*r)[1], owner + ": range");
    }
    if (auto r = optional(n, "rate")) {
      remember(c.where, "rate", *r);
      c.rate = number(*r, owner + ": rate");
    }
    if (auto z = optional(n, "noise")) {
      remember(c.where, "noise", *z);
      if (!z->IsMap()) fail(*z, owner + ": noise must be a mapping {a, b, quantum_mm, edge_dropout}, found " + describe(*z));
      check_keys(*z, kNoiseKeys, owner + " noise");
      auto field = [&](const char* key, double& out) {
        if (auto v = optional(*z, key)) {
          out = number(*v, owner + ": noise " + key);
          if (!(out >= 0)) fail(*v, owner + ": noise " + key + " must not be negative");
        }
      };
      field("a", c.noise.a);
      field("b", c.noise.b);
      field("quantum_mm", c.noise.quantum_mm);
      field("edge_dropout", c.noise.edge_dropout);
      if (auto v = optional(*z, "edge_dropout"); v && c.noise.edge_dropout > 1)
        fail(*v, owner + ": noise edge_dropout is a probability (at most 1)");
    }
    return c;
  }

  void read_colours(const YAML::Node& n, std::vector<ClassColour>& out) {
    if (!n.IsMap()) fail(n, "colours must be a mapping of class: [r, g, b] (each in [0, 1]), found " + describe(n));
    std::set<std::string> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node key = it->first, value = it->second;  // copies: it-> yields a temporary
      ClassColour c;
      c.cls = word(key, "colours: a class");
      c.where = loc(key);
      if (!seen.insert(c.cls).second) fail(key, "duplicate class " + quoted(c.cls) + " in colours");
      const std::string what = "colours: " + quoted(c.cls);
      if (!value.IsSequence() || value.size() != 3)
        fail(value, what + " must be a list [r, g, b] of three numbers in [0, 1], found " + describe(value));
      for (std::size_t i = 0; i < 3; ++i) {
        c.rgb[i] = number(value[i], what);
        if (c.rgb[i] < 0 || c.rgb[i] > 1) fail(value[i], what + ": each channel lies in [0, 1], found " + describe(value[i]));
      }
      out.push_back(std::move(c));
    }
  }

  void read_propositions(const YAML::Node& n, std::vector<Proposition>& out) {
    if (!n.IsMap())
      fail(n, "propositions must be a mapping of name: \"expression\" (e.g. all_in_r2: \"all block in r2\"), found " +
                  describe(n));
    std::set<std::string> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node key = it->first, value = it->second;  // copies: it-> yields a temporary
      if (!key.IsScalar()) fail(key, "proposition names must be words, found " + describe(key));
      Proposition p;
      p.name = key.Scalar();
      if (!seen.insert(p.name).second) fail(key, "duplicate proposition " + quoted(p.name));
      if (value.IsNull()) fail(key, "proposition " + quoted(p.name) + " has no expression");
      if (!value.IsScalar())
        fail(value, "proposition " + quoted(p.name) + " must be an expression in quotes, found " + describe(value));
      p.text = text_value(value, "proposition " + quoted(p.name));
      p.where = text_start(value);
      p.layout = text_layout(value);
      remember(p.where, "name", key);
      p.expr = parse_prop_expr(p.text, p.where, p.layout);
      out.push_back(std::move(p));
    }
  }

  // An operator entry `{time, action: new_task, task, propositions}`.
  static bool is_new_task(const YAML::Node& n) {
    if (!n.IsMap()) return false;
    const YAML::Node a = n["action"];
    return a && a.IsScalar() && a.Scalar() == kNewTask;
  }

  TaskChange read_task_change(const YAML::Node& n) {
    TaskChange c;
    c.where = loc(n);
    const std::string owner = std::string("operator action '") + kNewTask + "'";
    check_keys(n, {"time", "action", "task", "propositions"}, owner);
    const YAML::Node t = required(n, "time", owner, c.where);
    remember(c.where, "time", t);
    c.time = number(t, "operator action time");
    const YAML::Node task = required(n, "task", owner, c.where);
    c.task = text_value(task, owner + ": task");
    c.task_where = text_start(task);
    c.task_layout = text_layout(task);
    if (auto p = optional(n, "propositions")) read_propositions(*p, c.propositions);
    return c;
  }

  Intervention read_intervention(const YAML::Node& n) {
    if (!n.IsMap()) fail(n, "an operator action must be a mapping {time, action, ...}, found " + describe(n));
    Intervention iv;
    iv.where = loc(n);
    const YAML::Node a = required(n, "action", "operator action", iv.where);
    const std::string action = word(a, "operator action");
    const ActionSpec* spec = nullptr;
    std::vector<std::string> names;
    for (const ActionSpec& s : action_specs()) {
      names.emplace_back(s.name);
      if (action == s.name) spec = &s;
    }
    names.emplace_back(kNewTask);
    if (!spec) fail(a, "unknown operator action " + quoted(action) + suggestion(action, names));
    iv.kind = spec->kind;
    std::vector<std::string> allowed = {"time", "action"};
    allowed.insert(allowed.end(), spec->keys.begin(), spec->keys.end());
    check_keys(n, allowed, "operator action '" + action + "'");
    const YAML::Node t = required(n, "time", "operator action '" + action + "'", iv.where);
    remember(iv.where, "time", t);
    iv.time = number(t, "operator action time");
    const std::string owner = "operator action '" + action + "'";
    auto o = optional(n, "object");
    auto c = optional(n, "container");
    if (o && c) fail(*c, owner + " names both an object and a container; give one");
    if (o || c) {
      const YAML::Node& subj = o ? *o : *c;
      remember(iv.where, o ? "object" : "container", subj);
      remember(iv.where, o ? "container" : "object", subj);
      iv.subject = word(subj, owner + ": " + (o ? "object" : "container"));
    } else if (iv.kind != Intervention::Kind::TakeFromGripper) {
      const char* needed = (iv.kind == Intervention::Kind::AddContainer || iv.kind == Intervention::Kind::RemoveContainer)
                               ? "container"
                               : "object";
      fail(n, owner + " is missing the required key '" + needed + "'");
    }
    if (iv.kind == Intervention::Kind::Add) iv.cls = "block";
    if (iv.kind == Intervention::Kind::AddContainer) iv.cls = "tray";
    if (auto cls = optional(n, "class")) {
      remember(iv.where, "class", *cls);
      iv.cls = word(*cls, owner + ": class");
    }
    if (auto to = optional(n, "to")) {
      remember(iv.where, "to", *to);
      iv.location = word(*to, owner + ": to");
    }
    if (auto p = optional(n, "position")) {
      remember(iv.where, "position", *p);
      iv.position = vec(*p, owner + ": position", 2);
    }
    return iv;
  }

  std::string_view text_;
  std::string source_;
  std::map<std::tuple<int, int, std::string>, SourceLocation> fields_;
};

// ---------------------------------------------------------------- writing

std::string num(double v) {
  char buf[64];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc()) return "0";
  return std::string(buf, ptr);
}

std::string vec(const Vec3& v, int dims = 3) {
  std::string out = "[";
  for (int i = 0; i < dims; ++i) {
    if (i) out += ", ";
    out += num(v[i]);
  }
  return out + "]";
}

// A YAML string: plain when it is an identifier that YAML would not read as
// something else, double-quoted otherwise.
std::string str(const std::string& s) {
  static const std::set<std::string> special = {"true", "false", "null", "yes", "no", "on", "off", "y", "n", "~"};
  bool plain = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_');
  for (char c : s) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  std::string lower = s;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (plain && !special.count(lower)) return s;
  std::string out = "\"";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (u < 0x20 || u == 0x7f) {
          static const char* hex = "0123456789abcdef";
          out += "\\x";
          out += hex[u >> 4];
          out += hex[u & 15];
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string quoted_str(const std::string& s) {
  std::string q = str(s);
  if (!q.empty() && q[0] == '"') return q;
  return "\"" + q + "\"";
}

const char* action_key(Intervention::Kind k) {
  for (const ActionSpec& s : action_specs())
    if (s.kind == k) return s.name;
  return "relocate";
}

}  // namespace

Scenario parse_scenario(std::string_view yaml_text, const std::string& source_name) {
  try {
    return Reader(yaml_text, source_name).read();
  } catch (const Error&) {
    throw;
  } catch (const YAML::Exception& e) {
    const SourceLocation at = e.mark.is_null() ? SourceLocation{source_name, 0, 0}
                                               : SourceLocation{source_name, e.mark.line + 1, e.mark.column + 1};
    throw Error("invalid YAML: " + e.msg, at);
  }
}

Scenario load_scenario(const std::string& path_or_builtin) {
  if (auto text = builtin_scenario_text(path_or_builtin))
    return parse_scenario(*text, path_or_builtin + " (built-in)");
  if (!path_exists(path_or_builtin)) {
    std::string names;
    for (const std::string& n : builtin_scenario_names()) names += (names.empty() ? "" : ", ") + n;
    throw Error("cannot read scenario " + quoted(path_or_builtin) +
                ": no such file, and no built-in scenario of that name (built-ins: " + names + ")");
  }
  return parse_scenario(read_text_file(path_or_builtin, "scenario", kMaxScenarioBytes), path_or_builtin);
}

std::string to_yaml(const Scenario& s) {
  std::ostringstream out;
  out << "# rtamp scenario (format: docs/scenario.md)\n";
  out << "name: " << str(s.name) << "\n";
  if (!s.description.empty()) out << "description: " << quoted_str(s.description) << "\n";
  out << "robot: {model: " << str(s.robot.model) << ", base: " << vec(s.robot.base) << ", yaw: " << num(s.robot.yaw)
      << "}\n";
  out << "regions:\n";
  for (const Region& r : s.regions)
    out << "  - {name: " << str(r.name) << ", center: " << vec(r.center)
        << ", size: " << vec(r.size, r.size[2] == 0 ? 2 : 3) << ", capacity: " << r.capacity << "}\n";
  if (!s.containers.empty()) {
    out << "containers:\n";
    for (const Container& c : s.containers)
      out << "  - {name: " << str(c.name) << ", class: " << str(c.cls) << ", position: " << vec(c.position)
          << ", size: " << vec(c.size) << ", capacity: " << c.capacity << "}\n";
  }
  out << "objects:" << (s.objects.empty() ? " []" : "") << "\n";
  for (const Object& o : s.objects)
    out << "  - {name: " << str(o.name) << ", class: " << str(o.cls) << ", position: " << vec(o.position)
        << ", size: " << vec(o.size) << "}\n";
  if (!s.propositions.empty()) {
    out << "propositions:\n";
    for (const Proposition& p : s.propositions) out << "  " << str(p.name) << ": " << quoted_str(p.text) << "\n";
  }
  out << "task: " << quoted_str(s.task) << "\n";
  if (!s.interventions.empty() || !s.task_changes.empty()) {
    std::set<std::string> containers;
    for (const Container& c : s.containers) containers.insert(c.name);
    for (const Intervention& iv : s.interventions)
      if (iv.kind == Intervention::Kind::AddContainer) containers.insert(iv.subject);
    out << "operator:\n";
    for (const Intervention& iv : s.interventions) {
      out << "  - {time: " << num(iv.time) << ", action: " << action_key(iv.kind);
      const bool cont = iv.kind == Intervention::Kind::AddContainer || iv.kind == Intervention::Kind::RemoveContainer ||
                        (iv.kind == Intervention::Kind::Relocate && containers.count(iv.subject));
      if (iv.kind != Intervention::Kind::TakeFromGripper || !iv.subject.empty())
        out << ", " << (cont ? "container" : "object") << ": " << str(iv.subject);
      if (iv.kind == Intervention::Kind::Add || iv.kind == Intervention::Kind::AddContainer)
        out << ", class: " << str(iv.cls);
      if (!iv.location.empty()) out << ", to: " << str(iv.location);
      if (iv.position) out << ", position: " << vec(*iv.position);
      out << "}\n";
    }
    for (const TaskChange& c : s.task_changes) {
      out << "  - {time: " << num(c.time) << ", action: " << kNewTask << ", task: " << quoted_str(c.task);
      if (!c.propositions.empty()) {
        out << ", propositions: {";
        for (std::size_t i = 0; i < c.propositions.size(); ++i)
          out << (i ? ", " : "") << str(c.propositions[i].name) << ": " << quoted_str(c.propositions[i].text);
        out << "}";
      }
      out << "}\n";
    }
  }
  if (!s.colours.empty()) {
    out << "colours:\n";
    for (const ClassColour& c : s.colours) out << "  " << str(c.cls) << ": " << vec(c.rgb) << "\n";
  }
  if (!s.cameras.empty()) {
    out << "cameras:\n";
    for (const Camera& c : s.cameras) {
      out << "  - {name: " << str(c.name) << ", mount: " << to_string(c.mount) << ", position: " << vec(c.position);
      if (c.mount == Camera::Mount::Fixed) out << ", look_at: " << vec(c.look_at);
      out << ", resolution: [" << c.width << ", " << c.height << "], fov: " << num(c.fovy) << ", range: ["
          << num(c.near) << ", " << num(c.far) << "], rate: " << num(c.rate) << ", noise: {a: " << num(c.noise.a)
          << ", b: " << num(c.noise.b) << ", quantum_mm: " << num(c.noise.quantum_mm)
          << ", edge_dropout: " << num(c.noise.edge_dropout) << "}}\n";
    }
  }
  return out.str();
}

}  // namespace rtamp::world
