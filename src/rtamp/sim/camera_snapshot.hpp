// A camera's images written to files (`rtamp sim --camera NAME --snapshot/--depth/
// --segmentation`, docs/perception.md): RGB as an 8-bit PNG; depth as a 16-bit grey
// PNG in millimetres (0 = no reading; depths past 65.535 m read 65535); the
// segmentation pass as an RGB PNG, one colour per body (the thing's own colour for a
// thing of the simulation, a fixed colour by body id for the rest), background black.
#pragma once

#include <string>

#include "rtamp/sim/camera_rig.hpp"

namespace rtamp::sim {

struct CameraFiles {
  std::string rgb, depth, segmentation;  // "" = not written
};

// Renders `camera` of `rig` once (noise on; the segmentation pass only if asked for)
// and writes the files asked for. Throws rtamp::Error when a file cannot be written.
void write_camera_snapshot(CameraRig& rig, std::size_t camera, const Simulation& sim, const CameraFiles& files);

}  // namespace rtamp::sim
