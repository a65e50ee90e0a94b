// One frame of the scene (docs/serve.md "frame"): the arm's joint angles (the
// MuJoCo qpos of the UR5's six joints; none in the symbolic world), the tool
// point, the held thing and every present thing's pose (the centre of its
// base, a unit quaternion w x y z) and location. Written as the `frame`
// message to pages and, at a low rate, as the `frame` record of a served
// episode's log (docs/exec.md), which replays read back.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

struct Frame {
  struct Thing {
    std::string name, cls;
    bool container = false;
    world::Vec3 pos{0, 0, 0};
    std::array<double, 4> quat{1, 0, 0, 0};
    world::Vec3 size{0, 0, 0};
    std::string at;  // region, container, "hand" or "none"
  };
  double t = 0;
  std::optional<std::array<double, 6>> q;
  world::Vec3 tool{0, 0, 0};
  std::string held;  // "" = none
  std::vector<Thing> things;
};

// {"type":"frame",...}: full precision for pages.
std::string frame_message(const Frame& f);
// {"ev":"frame",...} without "t" (EpisodeLog::record adds it): millimetres and
// milliradians, for the log.
std::string frame_record(const Frame& f);
// A log's frame record (parsed JSON text) as a frame message (rtamp::Error if it is not one).
std::string frame_message_from_record(const std::string& record);

}  // namespace rtamp::serve
