#include "rtamp/episode/mcap_camera.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "rtamp/sim/camera_overlay.hpp"
#include "rtamp/sim/renderer.hpp"
#include "rtamp/util/base64.hpp"
#include "rtamp/util/json_text.hpp"

namespace rtamp::episode {

namespace {

using nlohmann::json;

// JSON Schemas after the Foxglove schemas of the same names (the fields written here).
json object(json properties) { return {{"type", "object"}, {"properties", std::move(properties)}}; }

const json& time_schema() {
  static const json t = object({{"sec", {{"type", "integer"}, {"minimum", 0}}},
                                {"nsec", {{"type", "integer"}, {"minimum", 0}, {"maximum", 999999999}}}});
  return t;
}

std::string image_schema() {
  json s = object({{"timestamp", time_schema()},
                   {"frame_id", {{"type", "string"}}},
                   {"data", {{"type", "string"}, {"contentEncoding", "base64"}}},
                   {"format", {{"type", "string"}}}});
  s["title"] = "foxglove.CompressedImage";
  s["description"] = "A compressed image";
  return s.dump();
}

std::string annotations_schema() {
  const json colour = object({{"r", {{"type", "number"}}}, {"g", {{"type", "number"}}}, {"b", {{"type", "number"}}},
                              {"a", {{"type", "number"}}}});
  const json point = object({{"x", {{"type", "number"}}}, {"y", {{"type", "number"}}}});
  const json points = object({{"timestamp", time_schema()},
                              {"type", {{"type", "integer"}, {"description", "2: line loop"}}},
                              {"points", {{"type", "array"}, {"items", point}}},
                              {"outline_color", colour},
                              {"outline_colors", {{"type", "array"}, {"items", colour}}},
                              {"fill_color", colour},
                              {"thickness", {{"type", "number"}, {"minimum", 0}}}});
  const json text = object({{"timestamp", time_schema()},
                            {"position", point},
                            {"text", {{"type", "string"}}},
                            {"font_size", {{"type", "number"}, {"minimum", 0}}},
                            {"text_color", colour},
                            {"background_color", colour}});
  json s = object({{"circles", {{"type", "array"}}},
                   {"points", {{"type", "array"}, {"items", points}}},
                   {"texts", {{"type", "array"}, {"items", text}}}});
  s["title"] = "foxglove.ImageAnnotations";
  s["description"] = "Annotations of an image: the detections' boxes and labels";
  return s.dump();
}

void put_stamp(std::string& o, double t) {
  const auto ns = static_cast<std::uint64_t>(std::llround(std::max(t, 0.0) * 1e9));
  o += "{\"sec\":" + std::to_string(ns / 1000000000ULL) + ",\"nsec\":" + std::to_string(ns % 1000000000ULL) + "}";
}

void put_colour(std::string& o, const std::array<std::uint8_t, 3>& rgb, double a) {
  o += "{\"r\":";
  json_text::append_number(o, rgb[0] / 255.0);
  o += ",\"g\":";
  json_text::append_number(o, rgb[1] / 255.0);
  o += ",\"b\":";
  json_text::append_number(o, rgb[2] / 255.0);
  o += ",\"a\":";
  json_text::append_number(o, a);
  o += '}';
}

void put_point(std::string& o, double x, double y) {
  o += "{\"x\":";
  json_text::append_number(o, x);
  o += ",\"y\":";
  json_text::append_number(o, y);
  o += '}';
}

// One annotation a box, each an object starting with its timestamp, then `rest(box)`'s fields.
template <class Rest>
void per_box(std::string& o, double t, const std::vector<sim::OverlayBox>& boxes, Rest rest) {
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    o += i ? ",{\"timestamp\":" : "{\"timestamp\":";
    put_stamp(o, t);
    rest(boxes[i]);
    o += '}';
  }
}

// The boxes as a foxglove.ImageAnnotations message: a line loop and a label each.
void annotations(std::string& o, double t, const std::vector<sim::OverlayBox>& boxes) {
  o = "{\"circles\":[],\"points\":[";
  per_box(o, t, boxes, [&](const sim::OverlayBox& b) {
    o += ",\"type\":2,\"points\":[";
    put_point(o, b.x0, b.y0);
    o += ',';
    put_point(o, b.x1, b.y0);
    o += ',';
    put_point(o, b.x1, b.y1);
    o += ',';
    put_point(o, b.x0, b.y1);
    o += "],\"outline_color\":";
    put_colour(o, b.rgb, 1);
    o += ",\"outline_colors\":[],\"fill_color\":";
    put_colour(o, b.rgb, 0);
    o += ",\"thickness\":2";
  });
  o += "],\"texts\":[";
  per_box(o, t, boxes, [&](const sim::OverlayBox& b) {
    o += ",\"position\":";
    put_point(o, b.x0, b.y0);
    o += ",\"text\":";
    json_text::append_string(o, b.label);
    o += ",\"font_size\":12,\"text_color\":{\"r\":0,\"g\":0,\"b\":0,\"a\":1},\"background_color\":";
    put_colour(o, b.rgb, 0.8);
  });
  o += "]}";
}

}  // namespace

McapCamera::McapCamera(EpisodeMcap& mcap, const std::string& camera, double period)
    : mcap_(mcap), frame_id_("camera/" + camera), period_(period) {
  image_ = mcap_.add_channel("/camera/" + camera + "/image", "foxglove.CompressedImage", image_schema());
  annotations_ = mcap_.add_channel("/camera/" + camera + "/annotations", "foxglove.ImageAnnotations",
                                   annotations_schema());
}

void McapCamera::frame(double t, const sim::CameraPerception& frame) {
  if (next_ >= 0 && t + 1e-9 < next_) return;
  next_ = t + period_;
  const sim::CameraImage& image = frame.image();
  png_ = sim::encode_png(image.rgb, image.width, image.height);
  text_ = "{\"timestamp\":";
  put_stamp(text_, t);
  text_ += ",\"frame_id\":";
  json_text::append_string(text_, frame_id_);
  text_ += ",\"data\":\"";
  base64::append(text_, png_);
  text_ += "\",\"format\":\"png\"}";
  mcap_.write(image_, t, text_);
  annotations(text_, t, sim::overlay_boxes(frame));
  mcap_.write(annotations_, t, text_);
  ++images_;
}

}  // namespace rtamp::episode
