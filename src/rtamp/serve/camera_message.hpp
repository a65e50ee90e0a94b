// A frame of camera perception as the `camera` message to pages (docs/serve.md
// "camera"): {"type":"camera","camera":NAME,"t":T,"width":W,"height":H,"png":BASE64,
// "boxes":[{"x0","y0","x1","y1","cls","name","state","label","rgb":[R,G,B]}]} — the
// frame's RGB image as a base64 PNG and its detections' boxes (sim/camera_overlay.hpp),
// which the page's Camera panel draws over the image.
#pragma once

#include <string>

#include "rtamp/sim/camera_perception.hpp"

namespace rtamp::serve {

std::string camera_message(double t, const sim::CameraPerception& frame);

}  // namespace rtamp::serve
