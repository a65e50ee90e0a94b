#include "rtamp/serve/camera_message.hpp"

#include "rtamp/sim/camera_overlay.hpp"
#include "rtamp/sim/renderer.hpp"
#include "rtamp/util/base64.hpp"
#include "rtamp/util/json_text.hpp"

namespace rtamp::serve {

std::string camera_message(double t, const sim::CameraPerception& frame) {
  const sim::CameraImage& image = frame.image();
  std::string o = "{\"type\":\"camera\",\"camera\":";
  json_text::append_string(o, frame.camera_name());
  o += ",\"t\":";
  json_text::append_number(o, t);
  o += ",\"width\":" + std::to_string(image.width) + ",\"height\":" + std::to_string(image.height) + ",\"png\":\"";
  base64::append(o, sim::encode_png(image.rgb, image.width, image.height));
  o += "\",\"boxes\":[";
  bool first = true;
  for (const sim::OverlayBox& b : sim::overlay_boxes(frame)) {
    o += first ? "{" : ",{";
    first = false;
    for (const auto& [key, value] : {std::pair{"x0", b.x0}, {"y0", b.y0}, {"x1", b.x1}, {"y1", b.y1}}) {
      o += '"';
      o += key;
      o += "\":";
      json_text::append_number(o, value);
      o += ',';
    }
    for (const auto& [key, value] : {std::pair{"cls", &b.cls}, {"name", &b.name}, {"state", &b.state}, {"label", &b.label}}) {
      o += '"';
      o += key;
      o += "\":";
      json_text::append_string(o, *value);
      o += ',';
    }
    o += "\"rgb\":[" + std::to_string(b.rgb[0]) + "," + std::to_string(b.rgb[1]) + "," + std::to_string(b.rgb[2]) + "]}";
  }
  o += "]}";
  return o;
}

}  // namespace rtamp::serve
