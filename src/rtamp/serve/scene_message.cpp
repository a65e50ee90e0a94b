#include "rtamp/serve/scene_message.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include <nlohmann/json.hpp>

#include "rtamp/exec/episode_log.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/sim/mjcf_builder.hpp"
#include "rtamp/sim/scene_style.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/table.hpp"

namespace rtamp::serve {

using nlohmann::json;

namespace {

std::string hex(const std::array<double, 3>& c) {
  char buf[8];
  auto b = [](double v) { return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", b(c[0]), b(c[1]), b(c[2]));
  return buf;
}

json vec(const world::Vec3& v) { return json::array({v[0], v[1], v[2]}); }

}  // namespace

std::string class_colour_hex(const world::Scenario& s, const std::string& cls) { return hex(sim::class_colour(s, cls)); }

std::string hello_fields(const world::Scenario& s, const automata::Automaton& ba, const std::string& mode,
                         const std::string& world_name, std::optional<double> replay_duration) {
  const world::TableTop top = world::table_top(s);
  json scene;
  scene["table"] = {{"center", {(top.xmin + top.xmax) / 2, (top.ymin + top.ymax) / 2, -0.025}},
                    {"size", {top.xmax - top.xmin, top.ymax - top.ymin, 0.05}}};
  json regions = json::array();
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const auto& r = s.regions[i];
    regions.push_back({{"name", r.name},
                       {"center", vec(r.center)},
                       {"size", vec(r.size)},
                       {"capacity", r.capacity},
                       {"color", hex(sim::region_colour(i))}});
  }
  scene["regions"] = regions;
  const world::Placement initial = world::initial_placement(s);
  json things = json::array();
  json classes = json::array();
  std::set<std::string> seen_classes;
  auto add_class = [&](const std::string& cls, bool container) {
    if (seen_classes.insert(cls).second)
      classes.push_back({{"name", cls}, {"color", class_colour_hex(s, cls)}, {"kind", container ? "container" : "object"}});
  };
  for (const auto& c : s.containers) {
    things.push_back({{"name", c.name}, {"class", c.cls}, {"kind", "container"}, {"size", vec(c.size)},
                      {"pos", vec(c.position)}, {"capacity", c.capacity}, {"at", *initial.location_of(c.name)},
                      {"color", class_colour_hex(s, c.cls)}});
    add_class(c.cls, true);
  }
  for (const auto& o : s.objects) {
    things.push_back({{"name", o.name}, {"class", o.cls}, {"kind", "object"}, {"size", vec(o.size)},
                      {"pos", vec(o.position)}, {"at", *initial.location_of(o.name)},
                      {"color", class_colour_hex(s, o.cls)}});
    add_class(o.cls, false);
  }
  for (const auto& iv : s.interventions) {
    if (iv.kind == world::Intervention::Kind::Add) add_class(iv.cls, false);
    if (iv.kind == world::Intervention::Kind::AddContainer) add_class(iv.cls, true);
  }
  add_class("block", false);
  add_class("tray", true);
  scene["things"] = things;
  scene["classes"] = classes;
  const robot::DhParameters dh = robot::DhParameters::ur5();
  const sim::MjcfOptions mo;
  scene["robot"] = {{"base", vec(s.robot.base)},
                    {"yaw", s.robot.yaw},
                    {"dh", {{"d", dh.d}, {"a", dh.a}, {"alpha", dh.alpha}}},
                    {"tool_offset", robot::Ur5Kinematics::Config{}.tool_offset},
                    {"home", mo.home}};

  json j{{"mode", mode},
         {"world", world_name},
         {"scene", scene},
         {"task", s.task},
         {"automaton", json::parse(exec::automaton_json(ba))}};
  if (replay_duration) j["replay"] = {{"duration", *replay_duration}};
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace rtamp::serve
