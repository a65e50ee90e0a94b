// What an episode log's records say about the scene, shared by the MCAP writers
// of both profiles (episode_mcap.hpp: JSON, mcap_ros2.hpp: ros2): the scenario
// (given, or the built-in the `episode` record names) with its layout, the arm's
// kinematics at the robot's base and every thing's class; a placement record
// laid out in its locations (exec/thing_layout.hpp, the hand above the base); a
// `frame` record as an exec::Frame; a record checked to have "ev" and "t".
// Internal (nlohmann/json in its interface): not installed.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "rtamp/exec/frame.hpp"
#include "rtamp/exec/thing_layout.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode::detail {

struct LogScene {
  std::optional<world::Scenario> scenario;
  std::optional<exec::ThingLayout> layout;
  std::optional<robot::Ur5Kinematics> arm;
  std::map<std::string, std::pair<std::string, bool>> kinds;  // thing -> class, container

  void use(const world::Scenario& s);
  // The built-in scenario `name`, if there is no scenario yet and it is one.
  void use_builtin(const std::string& name);
  // The frame of a placement record ({thing: location}) at time t; null without a scenario.
  std::optional<exec::Frame> laid_out(double t, const nlohmann::json& placement);
};

// The MCAP Metadata record "rtamp" of an episode: library, version, and the
// `episode` record's scenario, task, world, seed and algorithm.
std::map<std::string, std::string> episode_metadata(const nlohmann::json& episode);

// A `frame` record (rtamp serve --log) as a frame: joint angles when it has six.
exec::Frame frame_of_record(double t, const nlohmann::json& record);

// A log record parsed: rtamp::Error unless a JSON object with a string "ev" and a number "t".
nlohmann::json parse_record(std::string_view record);

}  // namespace rtamp::episode::detail
