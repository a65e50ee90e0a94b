// rtamp log to-mcap: an episode's JSON Lines log converted to MCAP, in either
// profile (EpisodeMcap: JSON; McapRos2: ros2), record by record; a malformed
// record stops it with "LOG:LINE: what" and leaves no half-converted file. The ros2
// profile looks for `frame` records first: if there are any, the scene is theirs only.
#include <cstdio>
#include <fstream>
#include <memory>

#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/episode/mcap_ros2.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::episode {

std::uint64_t log_to_mcap(const std::string& log_path, const std::string& mcap_path, McapCompression compression,
                          const world::Scenario* scenario, std::size_t chunk_bytes, McapProfile profile) {
  std::ifstream in(log_path);
  if (!in) throw Error("cannot read the episode log '" + log_path + "'");
  std::string failure;
  std::uint64_t records = 0;
  {
    std::unique_ptr<EpisodeMcap> json;
    std::unique_ptr<McapRos2> ros2;
    if (profile == McapProfile::Ros2) {
      ros2 = std::make_unique<McapRos2>(mcap_path, compression, scenario, chunk_bytes);
      // One source for the scene: a log with `frame` records has it from them only.
      for (std::string line; std::getline(in, line);)
        if (line.find("\"ev\":\"frame\"") != std::string::npos) {
          ros2->scene_from_frame_records();
          break;
        }
      in.clear();
      in.seekg(0);
    } else
      json = std::make_unique<EpisodeMcap>(mcap_path, compression, scenario, chunk_bytes);
    std::string line;
    std::uint64_t n = 0;
    while (failure.empty() && std::getline(in, line)) {
      ++n;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      try {
        if (ros2)
          ros2->add(line);
        else
          json->add(line);
      } catch (const Error& e) {
        failure = log_path + ":" + std::to_string(n) + ": " + e.message();
      } catch (const std::exception& e) {
        failure = log_path + ":" + std::to_string(n) + ": " + e.what();
      }
    }
    if (failure.empty()) {
      if (ros2)
        ros2->close();
      else
        json->close();
    }
    records = ros2 ? ros2->records() : json->records();
  }
  if (!failure.empty()) {
    std::remove(mcap_path.c_str());  // no half-converted file
    throw Error(failure);
  }
  return records;
}

}  // namespace rtamp::episode
