// Frames of a world that cannot draw itself (World::frames() is null — a
// user's world, a real robot): what the loop perceived last, each thing laid
// out in its location (thing_layout.hpp), the hand at the location the last
// move ended at (above it), or above the robot's base before the first move.
// No joint angles. Reads the world's time() and hand() only.
#pragma once

#include "rtamp/exec/frame.hpp"
#include "rtamp/exec/thing_layout.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

class LaidOutFrames final : public FrameSource {
 public:
  // `world` must outlive this.
  LaidOutFrames(const world::Scenario& scenario, const World& world);
  Frame frame(const world::Placement& perceived) override;

 private:
  world::Vec3 hand_point(const world::Placement& perceived) const;

  world::Scenario scenario_;
  const World& world_;
  ThingLayout layout_;
};

}  // namespace rtamp::exec
