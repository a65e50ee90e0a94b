#include "rtamp/exec/laid_out_frames.hpp"

namespace rtamp::exec {

namespace {
constexpr double kHandHeight = 0.25;  // m above the location the hand is at
}

LaidOutFrames::LaidOutFrames(const world::Scenario& scenario, const World& world)
    : scenario_(scenario), world_(world), layout_(scenario) {}

world::Vec3 LaidOutFrames::hand_point(const world::Placement& perceived) const {
  const std::string at = world_.hand();
  world::Vec3 p = scenario_.robot.base;
  p[2] += 2 * kHandHeight;
  if (const world::Region* r = scenario_.find_region(at)) {
    p = r->center;
    p[2] += kHandHeight;
  } else if (!at.empty() && perceived.location_of(at)) {
    p = layout_.position(at);
    p[2] += kHandHeight;
  }
  return p;
}

Frame LaidOutFrames::frame(const world::Placement& perceived) {
  return layout_.frame(world_.time(), perceived, hand_point(perceived));
}

}  // namespace rtamp::exec
