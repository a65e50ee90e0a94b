#include "rtamp/sim/colour_segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "rtamp/sim/scene_style.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::sim {
namespace {

constexpr int kBits = 6;
constexpr int kLevels = 1 << kBits;
constexpr int kShift = 8 - kBits;
constexpr double kMinThingChroma = 0.1;  // a thing colour's channels must differ by this much

std::array<double, 3> unit(const std::array<double, 3>& c) {
  const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  if (n <= 0) return {0, 0, 0};
  return {c[0] / n, c[1] / n, c[2] / n};
}

// The chroma vector, the colour minus its smallest channel: its direction is the hue
// (shading scales it, white light leaves it), its largest entry the chroma.
double chroma_span(const std::array<double, 3>& c) {
  return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]});
}

std::array<double, 3> hue_direction(const std::array<double, 3>& c) {
  const double lo = std::min({c[0], c[1], c[2]});
  return unit({c[0] - lo, c[1] - lo, c[2] - lo});
}

}  // namespace

ColourSegmenter::ColourSegmenter(std::vector<KnownColour> colours, ColourSegmentationOptions options)
    : colours_(std::move(colours)), options_(options) {
  if (colours_.empty()) throw Error("colour segmentation: no known colours");
  if (colours_.size() > 32767) throw Error("colour segmentation: more than 32767 known colours");
  if (!(options_.max_angle_deg > 0 && options_.max_angle_deg < 90))
    throw Error("colour segmentation: max_angle_deg must lie in (0, 90)");
  if (options_.min_chroma < 0 || options_.min_chroma > 255 || options_.min_blob_pixels < 1 || options_.opening_radius < 0 ||
      !(options_.min_saturation >= 0 && options_.min_saturation < 1))
    throw Error("colour segmentation: min_chroma in [0, 255], min_saturation in [0, 1), min_blob_pixels >= 1, "
                "opening_radius >= 0");
  // A surface's pixel is roughly a * albedo + b * white (diffuse light, plus ambient and
  // specular light and clipping that whiten it): its chroma vector, the colour minus its
  // smallest channel, keeps the albedo's direction (its hue) whatever a and b are.
  std::vector<std::array<double, 3>> dirs;
  for (const KnownColour& k : colours_) {
    dirs.push_back(hue_direction(k.rgb));
    if (k.thing && chroma_span(k.rgb) < kMinThingChroma)
      throw Error("colour segmentation: the colour of '" + k.label + "' is too grey to find by its hue");
  }
  const double min_cos = std::cos(options_.max_angle_deg * std::numbers::pi / 180);
  table_.assign(static_cast<std::size_t>(kLevels) * kLevels * kLevels, -1);
  for (int r = 0; r < kLevels; ++r)
    for (int g = 0; g < kLevels; ++g)
      for (int b = 0; b < kLevels; ++b) {
        // The centre of the bin, in 8-bit units.
        const double half = 0.5 * (1 << kShift);
        const std::array<double, 3> c{(r << kShift) + half, (g << kShift) + half, (b << kShift) + half};
        const double span = chroma_span(c), hi = std::max({c[0], c[1], c[2]});
        if (span < options_.min_chroma || span < options_.min_saturation * hi) continue;
        const auto u = hue_direction(c);
        double best = min_cos;
        int label = -1;
        for (std::size_t k = 0; k < dirs.size(); ++k) {
          const double cs = u[0] * dirs[k][0] + u[1] * dirs[k][1] + u[2] * dirs[k][2];
          if (cs > best) best = cs, label = static_cast<int>(k);
        }
        table_[(static_cast<std::size_t>(r) * kLevels + g) * kLevels + b] = static_cast<std::int16_t>(label);
      }
}

void ColourSegmenter::segment(const std::uint8_t* rgb, int width, int height, ColourSegmentation& out) const {
  out.width = width;
  out.height = height;
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  out.label.resize(n);
  out.blobs.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = rgb + 3 * i;
    out.label[i] = table_[((static_cast<std::size_t>(p[0] >> kShift) * kLevels) + (p[1] >> kShift)) * kLevels +
                          (p[2] >> kShift)];
  }
  cv::Mat mask(height, width, CV_8U), components;
  const cv::Mat kernel = cv::getStructuringElement(
      cv::MORPH_RECT, cv::Size(2 * options_.opening_radius + 1, 2 * options_.opening_radius + 1));
  for (std::size_t k = 0; k < colours_.size(); ++k) {
    if (!colours_[k].thing) continue;
    const auto label = static_cast<std::int16_t>(k);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      const bool on = out.label[i] == label;
      mask.data[i] = on ? 255 : 0;
      any |= on;
    }
    if (!any) continue;
    if (options_.opening_radius > 0) cv::morphologyEx(mask, mask, cv::MORPH_OPEN, kernel);
    const int count = cv::connectedComponents(mask, components, 8, CV_32S);
    std::vector<ColourBlob> blobs(static_cast<std::size_t>(std::max(count - 1, 0)));
    const auto* comp = components.ptr<std::int32_t>();
    for (std::size_t i = 0; i < n; ++i) {
      if (comp[i] > 0) {
        blobs[static_cast<std::size_t>(comp[i] - 1)].pixels.push_back(static_cast<std::int32_t>(i));
      } else if (out.label[i] == label) {
        out.label[i] = -1;  // removed by the opening
      }
    }
    for (ColourBlob& b : blobs) {
      if (static_cast<int>(b.pixels.size()) < options_.min_blob_pixels) {
        for (std::int32_t i : b.pixels) out.label[static_cast<std::size_t>(i)] = -1;
        continue;
      }
      b.colour = k;
      out.blobs.push_back(std::move(b));
    }
  }
}

namespace {

SourceLocation where_class(const world::Scenario& s, const std::string& cls) {
  if (const auto* c = s.find_colour(cls)) return c->where;
  for (const auto& o : s.objects)
    if (o.cls == cls) return o.where;
  for (const auto& c : s.containers)
    if (c.cls == cls) return c.where;
  for (const auto& i : s.interventions)
    if (i.cls == cls) return i.where;
  return SourceLocation{s.source, 0, 0};
}

std::string colour_text(const std::array<double, 3>& c) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "[%.3g, %.3g, %.3g]", c[0], c[1], c[2]);
  return buf;
}

}  // namespace

void check_scene_colours(const world::Scenario& s, const ColourSegmentationOptions& options) {
  std::vector<KnownColour> things;
  for (KnownColour& k : scene_colours(s))
    if (k.thing) things.push_back(std::move(k));
  const double needed = 2 * options.max_angle_deg;
  for (std::size_t i = 0; i < things.size(); ++i) {
    const KnownColour& a = things[i];
    if (chroma_span(a.rgb) < kMinThingChroma)
      throw Error("class '" + a.label + "': its colour " + colour_text(a.rgb) +
                      " is too grey for the camera to find by its hue (channels differ by less than 0.1)",
                  where_class(s, a.label));
    for (std::size_t j = 0; j < i; ++j) {
      const KnownColour& b = things[j];
      const auto u = hue_direction(a.rgb), v = hue_direction(b.rgb);
      const double cs = std::clamp(u[0] * v[0] + u[1] * v[1] + u[2] * v[2], -1.0, 1.0);
      const double angle = std::acos(cs) * 180 / std::numbers::pi;
      if (angle < needed) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.1f", angle);
        // Blame the class defined later in the file (the one a user most likely just wrote).
        const SourceLocation wa = where_class(s, a.label), wb = where_class(s, b.label);
        const bool a_later = wa.line > wb.line || (wa.line == wb.line && wa.column >= wb.column);
        throw Error("classes '" + b.label + "' " + colour_text(b.rgb) + " and '" + a.label + "' " + colour_text(a.rgb) +
                        " look alike to the camera: their hues are " + buf + "° apart, and it tells classes apart at " +
                        std::to_string(static_cast<int>(needed)) + "° or more (give one a colour of its own in colours:)",
                    a_later ? wa : wb);
      }
    }
  }
}

std::vector<KnownColour> scene_colours(const world::Scenario& s) {
  std::set<std::string> classes;
  for (const auto& o : s.objects) classes.insert(o.cls);
  for (const auto& c : s.containers) classes.insert(c.cls);
  for (const auto& i : s.interventions)
    if (!i.cls.empty()) classes.insert(i.cls);
  classes.insert("block");
  classes.insert("tray");
  std::vector<KnownColour> out;
  for (const std::string& c : classes) out.push_back({c, class_colour(s, c), true});
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const auto c = region_colour(i);
    out.push_back({"region " + s.regions[i].name, c, false});
    out.push_back({"region " + s.regions[i].name + " fill", {0.5 + 0.5 * c[0], 0.5 + 0.5 * c[1], 0.5 + 0.5 * c[2]}, false});
  }
  // mjcf_builder.cpp and models/ur5.xml.
  out.push_back({"table", {0.93, 0.91, 0.86}, false});
  out.push_back({"floor", {0.82, 0.83, 0.85}, false});
  out.push_back({"arm", {0.5, 0.52, 0.56}, false});
  out.push_back({"arm housing", {0.2, 0.3, 0.55}, false});
  out.push_back({"arm pedestal", {0.25, 0.25, 0.28}, false});
  out.push_back({"gripper", {0.15, 0.15, 0.17}, false});
  out.push_back({"gripper finger", {0.3, 0.3, 0.33}, false});
  return out;
}

}  // namespace rtamp::sim
