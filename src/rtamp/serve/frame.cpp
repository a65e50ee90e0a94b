#include "rtamp/serve/frame.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "rtamp/util/json_text.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::serve {

using nlohmann::json;

namespace {

double round_to(double v, double unit) { return unit > 0 ? std::round(v / unit) * unit : v; }

template <typename A>
void append_array(std::string& out, const A& a, double unit) {
  out += '[';
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (i) out += ',';
    json_text::append_number(out, round_to(a[i], unit));
  }
  out += ']';
}

// The members after "type"/"ev" (and "t"), then the closing brace.
void append_body(std::string& out, const Frame& f, double unit, double angle_unit) {
  out += ",\"q\":";
  if (f.q) append_array(out, *f.q, angle_unit);
  else out += "null";
  out += ",\"tool\":";
  append_array(out, f.tool, unit);
  out += ",\"held\":";
  if (f.held.empty()) out += "null";
  else json_text::append_string(out, f.held);
  out += ",\"things\":[";
  for (std::size_t i = 0; i < f.things.size(); ++i) {
    const Frame::Thing& t = f.things[i];
    out += i ? ",{\"name\":" : "{\"name\":";
    json_text::append_string(out, t.name);
    out += ",\"class\":";
    json_text::append_string(out, t.cls);
    out += t.container ? ",\"kind\":\"container\",\"pos\":" : ",\"kind\":\"object\",\"pos\":";
    append_array(out, t.pos, unit);
    out += ",\"quat\":";
    append_array(out, t.quat, angle_unit);
    out += ",\"size\":";
    append_array(out, t.size, unit);
    out += ",\"at\":";
    json_text::append_string(out, t.at);
    out += '}';
  }
  out += "]}";
}

}  // namespace

std::string frame_message(const Frame& f) {
  std::string out;
  out.reserve(160 + 200 * f.things.size());
  out += "{\"type\":\"frame\",\"t\":";
  json_text::append_number(out, f.t);
  append_body(out, f, 0, 0);
  return out;
}

std::string frame_record(const Frame& f) {
  std::string out;
  out.reserve(120 + 160 * f.things.size());
  out += "{\"ev\":\"frame\"";
  append_body(out, f, 1e-3, 1e-3);
  return out;
}

std::string frame_message_from_record(const std::string& record) {
  json j = json::parse(record);
  if (!j.is_object() || j.value("ev", "") != "frame") throw Error("not a frame record");
  j.erase("ev");
  j["type"] = "frame";
  return j.dump();
}

}  // namespace rtamp::serve
