#include "rtamp/episode/camera_record.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace rtamp::episode {

namespace {

using json = nlohmann::json;

double round_to(double v, double step) { return std::round(v / step) * step; }

json point(const world::Vec3& p) {
  return json::array({round_to(p[0], 1e-4), round_to(p[1], 1e-4), round_to(p[2], 1e-4)});
}

}  // namespace

std::string camera_record(const sim::CameraPerception& frame) {
  json detections = json::array();
  for (const world::Detection& d : frame.detections())
    detections.push_back(
        {{"class", d.cls}, {"at", point(d.base)}, {"yaw", round_to(d.yaw, 1e-3)}, {"complete", d.complete}});
  json things = json::array();
  for (const world::BelievedThing& t : frame.belief().things())
    things.push_back({{"name", t.name}, {"class", t.cls}, {"state", world::to_string(t.state)}, {"at", point(t.base)}});
  return json{{"ev", "camera"}, {"camera", frame.camera_name()}, {"detections", detections}, {"things", things}}.dump();
}

}  // namespace rtamp::episode
