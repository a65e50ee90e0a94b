// rtamp log to-mcap: an episode's JSON Lines log converted to MCAP, in either
// profile (EpisodeMcap: JSON; McapRos2: ros2), record by record. The whole log is
// checked first (log_check.hpp, the check of `serve --replay`), so a log that is
// refused leaves the output as it was: not created, not truncated; a conversion or
// write that fails leaves no half-converted file (a FIFO or a device is never
// removed). The ros2 profile takes the scene from `frame` records only if there are any.
#include <memory>

#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/episode/log_check.hpp"
#include "rtamp/episode/mcap_ros2.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/output_file.hpp"

namespace rtamp::episode {

std::uint64_t log_to_mcap(const std::string& log_path, const std::string& mcap_path, McapCompression compression,
                          const world::Scenario* scenario, std::size_t chunk_bytes, McapProfile profile) {
  bool frames = false;
  read_episode_log(log_path, scenario, [&](const nlohmann::json& record, const std::string&, int) {
    frames = frames || record.value("ev", "") == "frame";
  });
  std::unique_ptr<EpisodeMcap> json;
  std::unique_ptr<McapRos2> ros2;
  if (profile == McapProfile::Ros2) {
    ros2 = std::make_unique<McapRos2>(mcap_path, compression, scenario, chunk_bytes, "OUT");
    if (frames) ros2->scene_from_frame_records();
  } else {
    json = std::make_unique<EpisodeMcap>(mcap_path, compression, scenario, chunk_bytes, "OUT");
  }
  try {
    read_episode_log(log_path, scenario, [&](const nlohmann::json&, const std::string& text, int line) {
      try {
        if (ros2)
          ros2->add(text);
        else
          json->add(text);
      } catch (const OutputError&) {
        throw;
      } catch (const Error& e) {
        throw Error(e.message(), SourceLocation{log_path, line, 0});
      }
    });
    if (ros2)
      ros2->close();
    else
      json->close();
  } catch (...) {
    if (ros2)
      ros2->discard();
    else
      json->discard();
    throw;
  }
  return ros2 ? ros2->records() : json->records();
}

}  // namespace rtamp::episode
