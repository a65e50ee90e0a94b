// What a frame of camera perception found, as boxes over its image (docs/perception.md
// "Seeing it"): the MCAP file's /camera/NAME/annotations and the page's Camera panel
// draw these same boxes. One box per detection: the box of the pixels the detected
// thing covers — the eight corners of the box the detector fitted (its class's size
// at the detection's base and yaw) projected with the frame's calibration, their
// bounding rectangle clipped to the image — labelled with the believed thing the
// detection is taken for (the nearest believed thing of its class within reach) and
// that thing's belief state, e.g. "o1 visible"; a detection near no believed thing of
// its class (a candidate not yet confirmed, a side face taken for a top) is "block new".
//
// Invariants: every box lies inside the image (0 <= x0 < x1 <= width, same for y);
// a detection whose box falls wholly outside the image or behind the camera has none;
// reads only the frame (image calibration, detections, belief), never the simulation.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/world/belief.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

class CameraPerception;

struct OverlayBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels: column, row; the image's top-left corner is (0, 0)
  std::string cls;
  std::string name;   // the believed thing ("" when none)
  std::string state;  // its state (world::to_string(ThingState)), or "new"
  std::string label;  // "o1 visible", "block new"
  std::array<std::uint8_t, 3> rgb{};  // the state's colour (visible green, occluded orange, held blue, ...)
};

std::vector<OverlayBox> overlay_boxes(const CameraImage& image, const std::vector<world::Detection>& detections,
                                      const world::Belief& belief);
std::vector<OverlayBox> overlay_boxes(const CameraPerception& frame);

}  // namespace rtamp::sim
