#include "rtamp/serve/frame.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "rtamp/util/error.hpp"

namespace rtamp::serve {

using nlohmann::json;

namespace {

double round_to(double v, double unit) { return std::round(v / unit) * unit; }

template <typename A>
json array_json(const A& a, double unit) {
  json j = json::array();
  for (double v : a) j.push_back(unit > 0 ? round_to(v, unit) : v);
  return j;
}

json frame_json(const Frame& f, double unit, double angle_unit) {
  json things = json::array();
  for (const auto& t : f.things)
    things.push_back({{"name", t.name},
                      {"class", t.cls},
                      {"kind", t.container ? "container" : "object"},
                      {"pos", array_json(t.pos, unit)},
                      {"quat", array_json(t.quat, angle_unit)},
                      {"size", array_json(t.size, unit)},
                      {"at", t.at}});
  return {{"q", f.q ? array_json(*f.q, angle_unit) : json(nullptr)},
          {"tool", array_json(f.tool, unit)},
          {"held", f.held.empty() ? json(nullptr) : json(f.held)},
          {"things", things}};
}

}  // namespace

std::string frame_message(const Frame& f) {
  json j{{"type", "frame"}, {"t", f.t}};
  j.update(frame_json(f, 0, 0));
  return j.dump();
}

std::string frame_record(const Frame& f) {
  json j{{"ev", "frame"}};
  j.update(frame_json(f, 1e-3, 1e-3));
  return j.dump();
}

std::string frame_message_from_record(const std::string& record) {
  json j = json::parse(record);
  if (!j.is_object() || j.value("ev", "") != "frame") throw Error("not a frame record");
  j.erase("ev");
  j["type"] = "frame";
  return j.dump();
}

}  // namespace rtamp::serve
