#include "rtamp/episode/mcap_profile.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::episode {

McapProfile parse_mcap_profile(const std::string& text) {
  if (text == "json") return McapProfile::Json;
  if (text == "ros2") return McapProfile::Ros2;
  throw Error("unknown MCAP profile '" + text + "' (json or ros2)");
}

const char* mcap_profile_name(McapProfile profile) { return profile == McapProfile::Ros2 ? "ros2" : "json"; }

}  // namespace rtamp::episode
