#include "rtamp/episode/detail/log_scene.hpp"

#include <vector>

#include "rtamp/util/error.hpp"
#include "rtamp/util/version.hpp"
#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode::detail {

using nlohmann::json;

void LogScene::use(const world::Scenario& s) {
  scenario = s;
  layout.emplace(s);
  robot::Ur5Kinematics::Config config;
  config.base = robot::Ur5Kinematics::base_pose(s.robot);
  arm.emplace(config);
  for (const auto& o : s.objects) kinds[o.name] = {o.cls, false};
  for (const auto& c : s.containers) kinds[c.name] = {c.cls, true};
}

void LogScene::use_builtin(const std::string& name) {
  if (!scenario && world::builtin_scenario_text(name)) use(world::load_scenario(name));
}

std::optional<exec::Frame> LogScene::laid_out(double t, const json& placement) {
  if (!layout || !placement.is_object()) return std::nullopt;
  world::Placement p;
  for (const auto& [name, where] : placement.items()) {
    const auto k = kinds.find(name);
    p.set(name, where.is_string() ? where.get<std::string>() : "none", k != kinds.end() ? k->second.first : "block",
          k != kinds.end() && k->second.second);
  }
  const world::Vec3 hand{scenario->robot.base[0], scenario->robot.base[1], scenario->robot.base[2] + 0.5};
  return layout->frame(t, p, hand);
}

std::map<std::string, std::string> episode_metadata(const json& episode) {
  std::map<std::string, std::string> m{{"library", "rtamp"}, {"version", version()}};
  for (const char* key : {"scenario", "task", "world", "seed", "algorithm"}) {
    const auto it = episode.find(key);
    if (it != episode.end() && !it->is_null()) m[key] = it->is_string() ? it->get<std::string>() : it->dump();
  }
  return m;
}

exec::Frame frame_of_record(double t, const json& j) {
  exec::Frame f;
  f.t = t;
  const auto q = j.find("q");
  if (q != j.end() && q->is_array() && q->size() == 6) {
    std::array<double, 6> angles{};
    for (std::size_t i = 0; i < 6; ++i) angles[i] = (*q)[i].is_number() ? (*q)[i].get<double>() : 0.0;
    f.q = angles;
  }
  if (const auto held = j.find("held"); held != j.end() && held->is_string()) f.held = held->get<std::string>();
  for (const auto& x : j.value("things", json::array())) {
    exec::Frame::Thing thing;
    thing.name = x.value("name", "");
    thing.cls = x.value("class", "");
    thing.container = x.value("kind", "") == "container";
    const auto pos = x.value("pos", std::vector<double>{0, 0, 0});
    const auto quat = x.value("quat", std::vector<double>{1, 0, 0, 0});
    const auto size = x.value("size", std::vector<double>{0, 0, 0});
    if (pos.size() == 3) thing.pos = {pos[0], pos[1], pos[2]};
    if (quat.size() == 4) thing.quat = {quat[0], quat[1], quat[2], quat[3]};
    if (size.size() == 3) thing.size = {size[0], size[1], size[2]};
    thing.at = x.value("at", "");
    f.things.push_back(std::move(thing));
  }
  return f;
}

json parse_record(std::string_view record) {
  json j = json::parse(record, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw Error("not a JSON object");
  const auto ev = j.find("ev");
  const auto t = j.find("t");
  if (ev == j.end() || !ev->is_string()) throw Error("a record without \"ev\"");
  if (t == j.end() || !t->is_number()) throw Error("a record without a time \"t\"");
  return j;
}

}  // namespace rtamp::episode::detail
