#include "rtamp/episode/episode_mcap.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "rtamp/episode/detail/log_scene.hpp"
#include "rtamp/exec/thing_layout.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/json_text.hpp"
#include "rtamp/util/version.hpp"
#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {

namespace {

using nlohmann::json;

// JSON Schemas of the channels, after the Foxglove schemas of the same names.
const char* const kTime =
    R"({"type":"object","properties":{"sec":{"type":"integer","minimum":0},"nsec":{"type":"integer","minimum":0,"maximum":999999999}}})";
const char* const kVec3 =
    R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"z":{"type":"number"}}})";
const char* const kQuat =
    R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"z":{"type":"number"},"w":{"type":"number"}}})";
const char* const kColor =
    R"({"type":"object","properties":{"r":{"type":"number"},"g":{"type":"number"},"b":{"type":"number"},"a":{"type":"number"}}})";

std::string log_schema() {
  return json{{"title", "foxglove.Log"},
              {"description", "A log message"},
              {"type", "object"},
              {"properties",
               {{"timestamp", json::parse(kTime)},
                {"level", {{"type", "integer"}, {"description", "0 unknown, 1 debug, 2 info, 3 warning, 4 error, 5 fatal"}}},
                {"message", {{"type", "string"}}},
                {"name", {{"type", "string"}}},
                {"file", {{"type", "string"}}},
                {"line", {{"type", "integer"}, {"minimum", 0}}}}}}
      .dump();
}

std::string scene_schema() {
  const json pose{{"type", "object"}, {"properties", {{"position", json::parse(kVec3)}, {"orientation", json::parse(kQuat)}}}};
  const json cube{{"type", "object"},
                  {"properties", {{"pose", pose}, {"size", json::parse(kVec3)}, {"color", json::parse(kColor)}}}};
  const json text{{"type", "object"},
                  {"properties",
                   {{"pose", pose},
                    {"billboard", {{"type", "boolean"}}},
                    {"font_size", {{"type", "number"}}},
                    {"scale_invariant", {{"type", "boolean"}}},
                    {"color", json::parse(kColor)},
                    {"text", {{"type", "string"}}}}}};
  const json entity{{"type", "object"},
                    {"properties",
                     {{"timestamp", json::parse(kTime)},
                      {"frame_id", {{"type", "string"}}},
                      {"id", {{"type", "string"}}},
                      {"lifetime", json::parse(kTime)},
                      {"frame_locked", {{"type", "boolean"}}},
                      {"metadata", {{"type", "array"}}},
                      {"arrows", {{"type", "array"}}},
                      {"cubes", {{"type", "array"}, {"items", cube}}},
                      {"spheres", {{"type", "array"}}},
                      {"cylinders", {{"type", "array"}}},
                      {"lines", {{"type", "array"}}},
                      {"triangles", {{"type", "array"}}},
                      {"texts", {{"type", "array"}, {"items", text}}},
                      {"models", {{"type", "array"}}}}}};
  const json deletion{{"type", "object"},
                      {"properties",
                       {{"timestamp", json::parse(kTime)},
                        {"type", {{"type", "integer"}, {"description", "0 matching id, 1 all"}}},
                        {"id", {{"type", "string"}}}}}};
  return json{{"title", "foxglove.SceneUpdate"},
              {"description", "An update to the entities displayed in a 3D scene"},
              {"type", "object"},
              {"properties",
               {{"deletions", {{"type", "array"}, {"items", deletion}}},
                {"entities", {{"type", "array"}, {"items", entity}}}}}}
      .dump();
}

std::string transforms_schema() {
  const json tf{{"type", "object"},
                {"properties",
                 {{"timestamp", json::parse(kTime)},
                  {"parent_frame_id", {{"type", "string"}}},
                  {"child_frame_id", {{"type", "string"}}},
                  {"translation", json::parse(kVec3)},
                  {"rotation", json::parse(kQuat)}}}};
  return json{{"title", "foxglove.FrameTransforms"},
              {"description", "An array of transforms between frames"},
              {"type", "object"},
              {"properties", {{"transforms", {{"type", "array"}, {"items", tf}}}}}}
      .dump();
}

std::string joint_states_schema() {
  const json joint{{"title", "foxglove.JointState"},
                   {"type", "object"},
                   {"properties", {{"name", {{"type", "string"}}}, {"position", {{"type", "number"}}}}},
                   {"required", {"name"}}};
  return json{{"title", "foxglove.JointStates"},
              {"description", "The states of a robot's joints"},
              {"type", "object"},
              {"properties", {{"timestamp", json::parse(kTime)}, {"joints", {{"type", "array"}, {"items", joint}}}}},
              {"required", {"timestamp", "joints"}}}
      .dump();
}

// rtamp's own channels: an object with a timestamp and the record's fields
// (`properties`, each {"type": ...}; docs/exec.md "The episode log").
std::string rtamp_schema(const std::string& title, const std::string& description, json properties,
                         std::initializer_list<const char*> required) {
  properties["timestamp"] = json::parse(kTime);
  json r = json::array({"timestamp"});
  for (const char* k : required) r.push_back(k);
  return json{{"title", title}, {"description", description}, {"type", "object"}, {"properties", properties}, {"required", r}}
      .dump();
}

json of_type(const char* type) { return {{"type", type}}; }
json array_of(const char* type) { return {{"type", "array"}, {"items", of_type(type)}}; }

std::string plan_schema() {
  return rtamp_schema("rtamp.Plan", "A plan: its moves, costs and search",
                      {{"first", of_type("boolean")},
                       {"cost", of_type("number")},
                       {"actions", array_of("string")},
                       {"costs", array_of("number")},
                       {"in_cycle", array_of("boolean")},
                       {"automaton_states", array_of("integer")},
                       {"start", of_type("object")},
                       {"hand", of_type("string")},
                       {"seconds", of_type("number")},
                       {"expanded", of_type("integer")},
                       {"generated", of_type("integer")},
                       {"cache_used", of_type("boolean")},
                       {"cache_hits", of_type("integer")},
                       {"cache_misses", of_type("integer")}},
                      {"actions", "costs", "in_cycle"});
}

std::string tree_schema() {
  return rtamp_schema("rtamp.TreeStatus", "The behavior tree: its last change and tick status",
                      {{"applied", of_type("boolean")},
                       {"deferred", of_type("boolean")},
                       {"inserted", of_type("integer")},
                       {"removed", of_type("integer")},
                       {"updated", of_type("integer")},
                       {"changes", of_type("integer")},
                       {"status", of_type("string")},
                       {"running", of_type("string")}},
                      {"status", "running"});
}

// The automaton of a task as exec::automaton_json gives it (the log's `episode` and
// `task` records): its states, its edges with their guards as text.
json automaton_properties() {
  const json state{{"type", "object"},
                   {"properties",
                    {{"id", {{"type", "integer"}, {"minimum", 0}}},
                     {"initial", {{"type", "boolean"}}},
                     {"accepting", {{"type", "boolean"}}}}},
                   {"required", {"id", "initial", "accepting"}}};
  const json edge{{"type", "object"},
                  {"properties",
                   {{"from", {{"type", "integer"}, {"minimum", 0}}},
                    {"to", {{"type", "integer"}, {"minimum", 0}}},
                    {"label", {{"type", "string"}, {"description", "the guard, a conjunction of atoms"}}},
                    {"accepting", {{"type", "boolean"}, {"description", "carries every acceptance mark (transition-based)"}}}}},
                  {"required", {"from", "to", "label"}}};
  return {{"states", {{"type", "array"}, {"items", state}}},
          {"edges", {{"type", "array"}, {"items", edge}}},
          {"state_based", {{"type", "boolean"}}}};
}

// /task: one message per task in force, when it took effect (the first task at the
// start, then every applied task change).
std::string task_schema() {
  const json automaton{{"type", "object"}, {"properties", automaton_properties()}, {"required", {"states", "edges"}}};
  return rtamp_schema("rtamp.Task", "The task in force from this time on (docs/exec.md \"A new task\")",
                      {{"task", {{"type", "string"}, {"description", "the LTL formula"}}},
                       {"by", {{"type", "string"}, {"description", "scenario, script, command line, page or api"}}},
                       {"automaton_states", {{"type", "integer"}, {"minimum", 0}}},
                       {"automaton", automaton},
                       {"propositions", {{"type", "object"}, {"description", "those the change brought: name -> expression"}}}},
                      {"task", "by"});
}

// /automaton: the task's Büchi automaton, at the same times as /task.
std::string automaton_schema() {
  json properties = automaton_properties();
  properties["task"] = of_type("string");
  return rtamp_schema("rtamp.Automaton", "The Büchi automaton of the task in force", properties,
                      {"task", "states", "edges"});
}

// /automaton/tracked: the states of /automaton consistent with the run so far, after a step.
std::string tracked_schema() {
  return rtamp_schema("rtamp.AutomatonStates", "The Büchi states tracked after a step of the run, and the run's state",
                      {{"automaton_states", {{"type", "array"}, {"items", {{"type", "integer"}, {"minimum", 0}}}}},
                       {"state", {{"type", "object"}, {"description", "thing -> location"}}}},
                      {"automaton_states", "state"});
}

std::uint64_t nanos(double t) { return t <= 0 ? 0 : static_cast<std::uint64_t>(std::llround(t * 1e9)); }

json stamp(std::uint64_t ns) { return {{"sec", ns / 1000000000ULL}, {"nsec", ns % 1000000000ULL}}; }

// The scene's text, written directly (a scene message for every perceived
// placement: building nlohmann objects for it cost most of a conversion).
void put_stamp(std::string& o, std::uint64_t ns) {
  o += "{\"sec\":";
  o += std::to_string(ns / 1000000000ULL);
  o += ",\"nsec\":";
  o += std::to_string(ns % 1000000000ULL);
  o += '}';
}

// The same, keys in nlohmann's order (messages that also carry a record's fields).
void put_sorted_stamp(std::string& o, std::uint64_t ns) {
  o += "{\"nsec\":";
  o += std::to_string(ns % 1000000000ULL);
  o += ",\"sec\":";
  o += std::to_string(ns / 1000000000ULL);
  o += '}';
}

void put_numbers(std::string& o, std::initializer_list<std::pair<const char*, double>> fields) {
  char sep = '{';
  for (const auto& [key, value] : fields) {
    o += sep;
    sep = ',';
    o += '"';
    o += key;
    o += "\":";
    json_text::append_number(o, value);
  }
  o += '}';
}

void put_pose(std::string& o, const world::Vec3& p, const std::array<double, 4>& wxyz) {
  o += "{\"position\":";
  put_numbers(o, {{"x", p[0]}, {"y", p[1]}, {"z", p[2]}});
  o += ",\"orientation\":";
  put_numbers(o, {{"x", wxyz[1]}, {"y", wxyz[2]}, {"z", wxyz[3]}, {"w", wxyz[0]}});
  o += '}';
}

// One entity of the scene, a cube (centre `centre`) and a label above it: its
// text after the timestamp (the part that stays while the thing stays put).
std::string entity_tail(std::string_view kind, const std::string& name, const world::Vec3& centre,
                        const std::array<double, 4>& quat, const world::Vec3& size, const std::array<double, 4>& rgba,
                        const world::Vec3& label_at) {
  std::string o = ",\"frame_id\":\"world\",\"id\":";
  json_text::append_string(o, std::string(kind) + name);
  o += ",\"lifetime\":{\"sec\":0,\"nsec\":0},\"frame_locked\":false,\"metadata\":[],\"arrows\":[],\"cubes\":[{\"pose\":";
  put_pose(o, centre, quat);
  o += ",\"size\":";
  put_numbers(o, {{"x", size[0]}, {"y", size[1]}, {"z", size[2]}});
  o += ",\"color\":";
  put_numbers(o, {{"r", rgba[0]}, {"g", rgba[1]}, {"b", rgba[2]}, {"a", rgba[3]}});
  o += "}],\"spheres\":[],\"cylinders\":[],\"lines\":[],\"triangles\":[],\"texts\":[{\"pose\":";
  put_pose(o, label_at, {1, 0, 0, 0});
  o += ",\"billboard\":true,\"font_size\":14,\"scale_invariant\":true,"
       "\"color\":{\"r\":1,\"g\":1,\"b\":1,\"a\":1},\"text\":";
  json_text::append_string(o, name);
  o += "}],\"models\":[]}";
  return o;
}

// A colour per block name (stable), trays brown.
std::array<double, 4> thing_color(const std::string& name, bool container) {
  if (container) return {0.55, 0.38, 0.22, 1};
  static const double palette[][3] = {{0.85, 0.2, 0.2}, {0.2, 0.6, 0.9}, {0.95, 0.75, 0.15},
                                      {0.3, 0.75, 0.35}, {0.65, 0.35, 0.8}, {0.95, 0.5, 0.15}};
  const auto k = std::hash<std::string>{}(name) % 6;
  return {palette[k][0], palette[k][1], palette[k][2], 1};
}

const char* const kJointNames[] = {"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                   "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};

std::string text_of(const json& j, const char* key) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return "";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

std::string join(const json& a) {
  std::string s;
  if (!a.is_array()) return s;
  for (const auto& x : a) {
    if (!s.empty()) s += ", ";
    s += x.is_string() ? x.get<std::string>() : x.dump();
  }
  return s;
}

}  // namespace

struct EpisodeMcap::Impl : detail::LogScene {  // the scenario, layout, arm and things' kinds
  McapWriter out;
  std::set<std::string> shown;                                // things on the scene now
  bool frames = false;                                        // the log has `frame` records
  bool live_arm = false;  // arm() was called: the arm comes from it, not from `frame` records
  std::string status, running;                                // the last tick's
  std::map<std::string, std::string> tree_fields;             // the last tree record's fields (their JSON)
  std::string scene_text;                                     // the scene message being written
  std::string scratch;                                        // another message being written
  std::vector<std::string> region_tails;                      // the regions' entities after their timestamps
  std::map<std::string, std::pair<std::array<double, 11>, std::string>> thing_tails;  // a thing's, with its pose
  std::uint16_t log, timeline, interventions, replans, plan, tree_ch, task_ch, automaton, tracked, scene, joints, tf;
  std::map<std::string, std::uint16_t> observer_schemas;  // add_channel's, by name

  Impl(const std::string& path, McapCompression c, const world::Scenario* s, std::size_t chunk_bytes,
       const std::string& what)
      : out(path, c, chunk_bytes, what, "", std::string("rtamp ") + version()) {
    const auto json_schema = [&](const std::string& name, const std::string& data) {
      return out.add_schema(name, "jsonschema", data);
    };
    const std::uint16_t log_s = json_schema("foxglove.Log", log_schema());
    log = out.add_channel("/rtamp/log", json_schema("rtamp.EpisodeLogRecord",
                                                    R"js({"title":"rtamp.EpisodeLogRecord","description":"A record of the rtamp episode log (docs/exec.md)","type":"object","properties":{"ev":{"type":"string"},"t":{"type":"number"}},"required":["ev","t"]})js"),
                          "json");
    timeline = out.add_channel("/timeline", log_s, "json");
    interventions = out.add_channel("/interventions", log_s, "json");
    replans = out.add_channel("/replans", log_s, "json");
    plan = out.add_channel("/plan", json_schema("rtamp.Plan", plan_schema()), "json");
    tree_ch = out.add_channel("/tree", json_schema("rtamp.TreeStatus", tree_schema()), "json");
    task_ch = out.add_channel("/task", json_schema("rtamp.Task", task_schema()), "json");
    automaton = out.add_channel("/automaton", json_schema("rtamp.Automaton", automaton_schema()), "json");
    tracked = out.add_channel("/automaton/tracked", json_schema("rtamp.AutomatonStates", tracked_schema()), "json");
    scene = out.add_channel("/scene", json_schema("foxglove.SceneUpdate", scene_schema()), "json");
    joints = out.add_channel("/joint_states", json_schema("foxglove.JointStates", joint_states_schema()), "json");
    tf = out.add_channel("/tf", json_schema("foxglove.FrameTransforms", transforms_schema()), "json");
    if (s) use(*s);
  }

  void put(std::uint16_t channel, std::uint64_t ns, const json& j) {
    const std::string text = j.dump(-1, ' ', false, json::error_handler_t::replace);
    out.write(channel, ns, ns, text);
  }

  // A foxglove.Log message, written as nlohmann would dump it (keys in order).
  void logline(std::uint16_t channel, std::uint64_t ns, int level, const std::string& ev, const std::string& message) {
    std::string& o = scratch;
    o = "{\"file\":\"\",\"level\":";
    o += std::to_string(level);
    o += ",\"line\":0,\"message\":";
    json_text::append_string(o, message);
    o += ",\"name\":";
    json_text::append_string(o, "rtamp." + ev);
    o += ",\"timestamp\":";
    put_sorted_stamp(o, ns);
    o += '}';
    out.write(channel, ns, ns, o);
  }

  // The scene: the regions and `things` (replacing what was shown; things gone deleted).
  void draw(std::uint64_t ns, const std::vector<exec::Frame::Thing>& things) {
    std::string& o = scene_text;
    o.clear();
    std::set<std::string> now;
    for (const auto& t : things)
      if (t.at != "none") now.insert(t.name);
    o += "{\"deletions\":[";
    bool first = true;
    for (const auto& name : shown) {
      if (now.count(name)) continue;
      o += first ? "{\"timestamp\":" : ",{\"timestamp\":";
      first = false;
      put_stamp(o, ns);
      o += ",\"type\":0,\"id\":";
      json_text::append_string(o, "thing/" + name);
      o += '}';
    }
    o += "],\"entities\":[";
    first = true;
    if (scenario && region_tails.size() != scenario->regions.size())
      for (const auto& r : scenario->regions)
        region_tails.push_back(entity_tail("region/", r.name, {r.center[0], r.center[1], r.center[2] + 0.001},
                                           {1, 0, 0, 0}, {r.size[0], r.size[1], 0.002}, {0.6, 0.6, 0.6, 0.35},
                                           {r.center[0], r.center[1], r.center[2] + 0.01}));
    const auto put_entity = [&](const std::string& tail) {
      o += first ? "{\"timestamp\":" : ",{\"timestamp\":";
      first = false;
      put_stamp(o, ns);
      o += tail;
    };
    for (const auto& tail : region_tails) put_entity(tail);
    for (const auto& t : things) {
      if (t.at == "none") continue;
      // A thing's text is made again only when it moved.
      const std::array<double, 11> key{t.pos[0],  t.pos[1],  t.pos[2],  t.quat[0], t.quat[1], t.quat[2],
                                       t.quat[3], t.size[0], t.size[1], t.size[2], t.container ? 1.0 : 0.0};
      auto& [cached_key, tail] = thing_tails[t.name];
      if (tail.empty() || cached_key != key) {
        cached_key = key;
        tail = entity_tail("thing/", t.name, {t.pos[0], t.pos[1], t.pos[2] + t.size[2] / 2}, t.quat, t.size,
                           thing_color(t.name, t.container), {t.pos[0], t.pos[1], t.pos[2] + t.size[2] + 0.03});
      }
      put_entity(tail);
    }
    o += "]}";
    shown = std::move(now);
    out.write(scene, ns, ns, o);
  }

  // A placement record ({thing: location}) laid out in its locations.
  void draw_placement(std::uint64_t ns, double t, const json& placement) {
    if (frames) return;
    if (const auto f = laid_out(t, placement)) draw(ns, f->things);
  }

  void draw_frame(std::uint64_t ns, const json& j) {
    frames = true;
    draw(ns, detail::frame_of_record(0, j).things);
    const auto q = j.find("q");
    if (live_arm || q == j.end() || !q->is_array() || q->size() != 6) return;
    std::array<double, 6> angles{};
    for (std::size_t i = 0; i < 6; ++i) angles[i] = (*q)[i].get<double>();
    draw_arm(ns, angles);
  }

  // The arm at joint angles `q`: /joint_states, and /tf as a chain world ->
  // ur5/base -> ur5/link1 .. ur5/link6 (each link in its parent), so that a 3-D
  // panel draws the arm as the lines between its frames.
  void draw_arm(std::uint64_t ns, const std::array<double, 6>& q) {
    std::string& o = scratch;
    o = "{\"timestamp\":";
    put_stamp(o, ns);
    o += ",\"joints\":[";
    for (std::size_t i = 0; i < 6; ++i) {
      o += i ? ",{\"name\":\"" : "{\"name\":\"";
      o += kJointNames[i];
      o += "\",\"position\":";
      json_text::append_number(o, q[i]);
      o += '}';
    }
    o += "]}";
    out.write(joints, ns, ns, o);
    if (!arm) return;
    const auto frames_now = arm->link_frames({q[0], q[1], q[2], q[3], q[4], q[5]});
    o = "{\"transforms\":[";
    for (std::size_t i = 0; i < frames_now.size(); ++i) {
      const Eigen::Isometry3d local = i == 0 ? frames_now[0] : frames_now[i - 1].inverse() * frames_now[i];
      const Eigen::Quaterniond r(local.rotation());
      const Eigen::Vector3d p = local.translation();
      o += i ? ",{\"timestamp\":" : "{\"timestamp\":";
      put_stamp(o, ns);
      o += ",\"parent_frame_id\":\"";
      o += i == 0 ? "world" : i == 1 ? "ur5/base" : "ur5/link" + std::to_string(i - 1);
      o += "\",\"child_frame_id\":\"";
      o += i == 0 ? std::string("ur5/base") : "ur5/link" + std::to_string(i);
      o += "\",\"translation\":";
      put_numbers(o, {{"x", p.x()}, {"y", p.y()}, {"z", p.z()}});
      o += ",\"rotation\":";
      put_numbers(o, {{"x", r.x()}, {"y", r.y()}, {"z", r.z()}, {"w", r.w()}});
      o += '}';
    }
    o += "]}";
    out.write(tf, ns, ns, o);
  }

  // The last tree record's fields and the tick's, keys in nlohmann's order.
  void tree_status(std::uint64_t ns) {
    std::string& o = scratch;
    o.clear();
    std::string stamp_text, status_text, running_text;
    put_sorted_stamp(stamp_text, ns);
    json_text::append_string(status_text, status);
    json_text::append_string(running_text, running);
    const std::pair<const char*, const std::string*> tick_fields[] = {
        {"running", &running_text}, {"status", &status_text}, {"timestamp", &stamp_text}};
    auto field = tree_fields.begin();
    char sep = '{';
    const auto put_field = [&](const std::string& key, const std::string& value) {
      o += sep;
      sep = ',';
      json_text::append_string(o, key);
      o += ':';
      o += value;
    };
    for (const auto& [key, value] : tick_fields) {
      for (; field != tree_fields.end() && field->first < key; ++field) put_field(field->first, field->second);
      if (field != tree_fields.end() && field->first == key) ++field;
      put_field(key, *value);
    }
    for (; field != tree_fields.end(); ++field) put_field(field->first, field->second);
    o += '}';
    out.write(tree_ch, ns, ns, o);
  }

  // A task took effect (the `episode` record's, an applied `task` record's): /task,
  // and /automaton when the record has the automaton (logs before it had none).
  void task_in_force(std::uint64_t ns, const json& j, const std::string& by) {
    json m{{"timestamp", stamp(ns)}, {"task", text_of(j, "task")}, {"by", by}};
    const auto a = j.find("automaton");
    const bool has_automaton = a != j.end() && a->is_object();
    if (has_automaton) {
      m["automaton_states"] = j.value("automaton_states", 0);
      m["automaton"] = *a;
    }
    if (const auto p = j.find("propositions"); p != j.end() && p->is_object()) m["propositions"] = *p;
    put(task_ch, ns, m);
    if (!has_automaton) return;
    json g = *a;
    g["timestamp"] = stamp(ns);
    g["task"] = m["task"];
    put(automaton, ns, g);
  }

  void tick(double t, std::string_view r, std::string_view s, std::string_view text) {
    const std::uint64_t ns = nanos(t);
    out.write(log, ns, ns, text);
    if (s != status || r != running) {
      status = s;
      running = r;
      tree_status(ns);
    }
  }

  void add(const json& j, std::string_view text) {
    const std::string ev = j.at("ev").get<std::string>();
    const double t = j.at("t").get<double>();
    const std::uint64_t ns = nanos(t);
    if (ev == "tick") {
      tick(t, text_of(j, "running"), text_of(j, "status"), text);
      return;
    }
    out.write(log, ns, ns, text);
    if (ev == "episode") {
      use_builtin(text_of(j, "scenario"));
      out.add_metadata("rtamp", detail::episode_metadata(j));
      logline(timeline, ns, 2, ev,
              "episode " + text_of(j, "scenario") + ": " + text_of(j, "task") + " (world " + text_of(j, "world") +
                  ", seed " + text_of(j, "seed") + ")");
      if (scenario) draw(ns, {});  // the regions, before anything is perceived
      task_in_force(ns, j, "scenario");
    } else if (ev == "task") {
      const bool applied = j.value("applied", false);
      logline(timeline, ns, applied ? 2 : 3, ev,
              "new task from " + text_of(j, "by") + ": " + text_of(j, "task") +
                  (applied ? " (" + text_of(j, "automaton_states") + " automaton states)" : " refused: " + text_of(j, "refused")));
      if (applied) task_in_force(ns, j, text_of(j, "by"));
    } else if (ev == "redirect") {
      logline(timeline, ns, 2, ev, "redirected " + text_of(j, "action") + ": " + text_of(j, "rule"));
    } else if (ev == "action") {
      const std::string what = text_of(j, "what"), why = text_of(j, "reason");
      logline(timeline, ns, what == "failed" ? 3 : 2, ev, what + " " + text_of(j, "action") + (why.empty() ? "" : ": " + why));
    } else if (ev == "intervention") {
      const bool applied = j.value("applied", false);
      std::string m = text_of(j, "kind") + " " + text_of(j, "subject");
      if (!text_of(j, "location").empty()) m += " -> " + text_of(j, "location");
      m += applied ? " (applied)" : " (refused)";
      if (!text_of(j, "detail").empty()) m += ": " + text_of(j, "detail");
      if (const auto c = j.find("class"); c != j.end() && c->is_string())
        kinds[text_of(j, "subject")] = {c->get<std::string>(), text_of(j, "kind").find("container") != std::string::npos};
      logline(interventions, ns, applied ? 2 : 3, ev, m);
      logline(timeline, ns, applied ? 2 : 3, ev, "intervention: " + m);
    } else if (ev == "perceived") {
      draw_placement(ns, t, j.value("placement", json::object()));
    } else if (ev == "things") {
      logline(timeline, ns, 2, ev, "things added [" + join(j.value("added", json::array())) + "] removed [" +
                                      join(j.value("removed", json::array())) + "]");
    } else if (ev == "run") {
      scratch = "{\"automaton_states\":";
      scratch += j.value("automaton_states", json::array()).dump(-1, ' ', false, json::error_handler_t::replace);
      scratch += ",\"state\":";
      scratch += j.value("state", json::object()).dump(-1, ' ', false, json::error_handler_t::replace);
      scratch += ",\"timestamp\":";
      put_sorted_stamp(scratch, ns);
      scratch += '}';
      out.write(tracked, ns, ns, scratch);
    } else if (ev == "handled_by_tree") {
      logline(timeline, ns, 2, ev, "handled by the tree: " + text_of(j, "by"));
    } else if (ev == "replan") {
      logline(replans, ns, 2, ev, "replan: " + text_of(j, "why"));
      logline(timeline, ns, 2, ev, "replan: " + text_of(j, "why"));
    } else if (ev == "plan") {
      json p = j;
      p.erase("ev");
      p.erase("t");
      p["timestamp"] = stamp(ns);
      put(plan, ns, p);
      logline(timeline, ns, 2, ev,
              std::string(j.value("first", false) ? "first plan" : "plan") + ", cost " + text_of(j, "cost") + ": " +
                  join(j.value("actions", json::array())));
    } else if (ev == "tree") {
      tree_fields.clear();
      for (const auto& [key, value] : j.items())
        if (key != "ev" && key != "t") tree_fields[key] = value.dump(-1, ' ', false, json::error_handler_t::replace);
      tree_status(ns);
      logline(timeline, ns, 2, ev,
              std::string(j.value("deferred", false) ? "tree change deferred" : "tree changed") + ": inserted " +
                  text_of(j, "inserted") + ", removed " + text_of(j, "removed") + ", updated " + text_of(j, "updated"));
    } else if (ev == "cycle") {
      logline(timeline, ns, 2, ev, "cycle " + text_of(j, "completed") + " completed");
    } else if (ev == "frame") {
      draw_frame(ns, j);
    } else if (ev == "statuses") {
      // Node statuses of a served episode (for its replay): in /log only.
    } else if (ev == "end") {
      draw_placement(ns, t, j.value("placement", json::object()));
      const bool success = j.value("success", false);
      logline(timeline, ns, success ? 2 : text_of(j, "end") == "error" ? 4 : 3, ev,
              std::string(success ? "success" : "no success") + " (" + text_of(j, "end") + ")" +
                  (text_of(j, "reason").empty() ? "" : ": " + text_of(j, "reason")));
    } else {
      logline(timeline, ns, 2, ev, std::string(text));
    }
  }
};

EpisodeMcap::EpisodeMcap(const std::string& path, McapCompression compression, const world::Scenario* scenario,
                         std::size_t chunk_bytes, const std::string& what)
    : impl_(std::make_unique<Impl>(path, compression, scenario, chunk_bytes, what)) {}

EpisodeMcap::~EpisodeMcap() = default;

namespace {

// A tick record as the log writes it ({"ev":"tick","running":"..","status":"..","t":T},
// no escapes): its fields without parsing JSON — half of a log's records are ticks.
bool tick_fields(std::string_view r, std::string_view& running, std::string_view& status, double& t) {
  constexpr std::string_view head = R"({"ev":"tick","running":")", mid = R"(","status":")", tail = R"(","t":)";
  if (r.substr(0, head.size()) != head || r.back() != '}' || r.find('\\') != std::string_view::npos) return false;
  const auto m = r.find(mid, head.size());
  if (m == std::string_view::npos) return false;
  const auto e = r.find(tail, m + mid.size());
  if (e == std::string_view::npos) return false;
  running = r.substr(head.size(), m - head.size());
  status = r.substr(m + mid.size(), e - m - mid.size());
  const std::string number(r.substr(e + tail.size(), r.size() - 1 - e - tail.size()));
  char* end = nullptr;
  t = std::strtod(number.c_str(), &end);
  return !number.empty() && end == number.c_str() + number.size() && std::isfinite(t);
}

}  // namespace

void EpisodeMcap::add(std::string_view record) {
  std::string_view running, status;
  double tick_time = 0;
  if (tick_fields(record, running, status, tick_time)) {
    impl_->tick(tick_time, running, status, record);
    ++records_;
    return;
  }
  impl_->add(detail::parse_record(record), record);
  ++records_;
}

void EpisodeMcap::arm(double t, const std::array<double, 6>& q) {
  impl_->live_arm = true;
  impl_->draw_arm(nanos(t), q);
}

std::uint16_t EpisodeMcap::add_channel(const std::string& topic, const std::string& schema_name,
                                       const std::string& schema) {
  auto [it, added] = impl_->observer_schemas.try_emplace(schema_name, 0);
  if (added) it->second = impl_->out.add_schema(schema_name, "jsonschema", schema);
  return impl_->out.add_channel(topic, it->second, "json");
}

void EpisodeMcap::write(std::uint16_t channel, double t, std::string_view message) {
  const std::uint64_t ns = nanos(t);
  impl_->out.write(channel, ns, ns, message);
}

void EpisodeMcap::close() { impl_->out.close(); }

void EpisodeMcap::discard() noexcept { impl_->out.discard(); }

}  // namespace rtamp::episode
