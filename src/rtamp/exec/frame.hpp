// One frame of the scene, for pictures of an episode (rtamp serve's page, a
// log's `frame` records): the arm's joint angles (the UR5's six, in worlds
// that have them), the tool point, the held thing and every present thing's
// pose (the centre of its base, a unit quaternion w x y z), size and location.
// A world draws its own frames if it can (FrameSource); otherwise things are
// laid out in their locations (thing_layout.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

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

// The optional capability of a world to draw itself (World::frames()). Called
// between the loop's steps, on the loop's thread; drawing must not change the
// episode (no draws from the world's random streams).
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The scene now; `perceived` is what the loop perceived last (a world may
  // label things with it).
  virtual Frame frame(const world::Placement& perceived) = 0;
};

}  // namespace rtamp::exec
