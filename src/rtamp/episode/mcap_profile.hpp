// Which MCAP profile an episode's file is written in (docs/formats.md "MCAP"):
// `json` (the default: JSON messages with JSON Schemas in Foxglove's
// conventions, episode_mcap.hpp) or `ros2` (the MCAP ros2 profile: CDR messages
// with ros2msg schemas on ROS 2's standard topics, what `ros2 bag play` and
// ROS 2 tools read, mcap_ros2.hpp).
#pragma once

#include <string>

namespace rtamp::episode {

enum class McapProfile { Json, Ros2 };

// "json", "ros2"; rtamp::Error naming the choices for anything else.
McapProfile parse_mcap_profile(const std::string& text);
const char* mcap_profile_name(McapProfile profile);

}  // namespace rtamp::episode
