// The episode log's `camera` record (docs/exec.md "The episode log"): what one frame of
// camera perception saw and believed — its detections (class, base, yaw, whether the
// whole outline was seen) and every believed thing's name, class, state and base.
// Invariants: one JSON object on one line with "ev": "camera" and no "t" (the log adds
// it); positions in metres rounded to 0.1 mm, yaws to 1 mrad.
#pragma once

#include <string>

#include "rtamp/sim/camera_perception.hpp"

namespace rtamp::episode {

std::string camera_record(const sim::CameraPerception& frame);

}  // namespace rtamp::episode
