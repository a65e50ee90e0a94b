#include "rtamp/sim/colour_segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "rtamp/sim/class_colours.hpp"
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
std::array<double, 3> hue_direction(const std::array<double, 3>& c) {
  const double lo = std::min({c[0], c[1], c[2]});
  return unit({c[0] - lo, c[1] - lo, c[2] - lo});
}

}  // namespace

double chroma_span(const std::array<double, 3>& c) {
  return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]});
}

double hue_angle_deg(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const auto u = hue_direction(a), v = hue_direction(b);
  if (u == std::array<double, 3>{0, 0, 0} || v == std::array<double, 3>{0, 0, 0}) return 0;
  const double cs = std::clamp(u[0] * v[0] + u[1] * v[1] + u[2] * v[2], -1.0, 1.0);
  return std::acos(cs) * 180 / std::numbers::pi;
}

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
  for (const KnownColour& k : colours_) thing_.push_back(k.thing);
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
  // Each pixel's label, and each thing colour's bounding box (x0, y0, x1, y1; empty: x0 > x1).
  std::vector<std::array<int, 4>>& box = out.boxes_;
  box.assign(colours_.size(), {width, height, -1, -1});
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* p = rgb + 3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    std::int16_t* label = out.label.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    // Flat faces give runs of one colour: a pixel like the one before it has its label.
    std::size_t cell = SIZE_MAX;
    std::int16_t l = -1;
    for (int x = 0; x < width; ++x, p += 3) {
      const std::size_t c = ((static_cast<std::size_t>(p[0] >> kShift) * kLevels) + (p[1] >> kShift)) * kLevels + (p[2] >> kShift);
      if (c != cell) cell = c, l = table_[c];
      label[x] = l;
      if (l >= 0 && thing_[static_cast<std::size_t>(l)]) {
        auto& b = box[static_cast<std::size_t>(l)];
        b[0] = std::min(b[0], x), b[1] = std::min(b[1], y), b[2] = std::max(b[2], x), b[3] = std::max(b[3], y);
      }
    }
  }
  // Each thing colour's mask is opened and split into blobs within its bounding box
  // grown by the opening's radius and a pixel: outside it the mask is empty, so the
  // opening and the blobs are the whole image's (the box's border behaves as the
  // image's own where they meet; OpenCV's defaults at the image border).
  const int r = options_.opening_radius;
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * r + 1, 2 * r + 1));
  for (std::size_t k = 0; k < colours_.size(); ++k) {
    const auto& b = box[k];
    if (!thing_[k] || b[0] > b[2]) continue;
    const int x0 = std::max(0, b[0] - r - 1), y0 = std::max(0, b[1] - r - 1);
    const int x1 = std::min(width - 1, b[2] + r + 1), y1 = std::min(height - 1, b[3] + r + 1);
    const int bw = x1 - x0 + 1, bh = y1 - y0 + 1;
    const auto label = static_cast<std::int16_t>(k);
    out.mask_.resize(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh));
    out.components_.resize(out.mask_.size());
    for (int y = 0; y < bh; ++y) {
      const std::int16_t* l = out.label.data() + static_cast<std::size_t>(y0 + y) * static_cast<std::size_t>(width) + x0;
      std::uint8_t* m = out.mask_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(bw);
      for (int x = 0; x < bw; ++x) m[x] = l[x] == label ? 255 : 0;
    }
    cv::Mat mask(bh, bw, CV_8U, out.mask_.data());
    cv::Mat components(bh, bw, CV_32S, out.components_.data());
    if (r > 0) cv::morphologyEx(mask, mask, cv::MORPH_OPEN, kernel);
    const int count = cv::connectedComponents(mask, components, 8, CV_32S);
    const std::size_t first = out.blobs.size();
    out.blobs.resize(first + static_cast<std::size_t>(std::max(count - 1, 0)));
    for (int y = 0; y < bh; ++y) {
      const std::int32_t* c = out.components_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(bw);
      const std::size_t row = static_cast<std::size_t>(y0 + y) * static_cast<std::size_t>(width) + x0;
      for (int x = 0; x < bw; ++x) {
        if (c[x] > 0) {
          out.blobs[first + static_cast<std::size_t>(c[x] - 1)].pixels.push_back(static_cast<std::int32_t>(row + x));
        } else if (out.label[row + x] == label) {
          out.label[row + x] = -1;  // removed by the opening
        }
      }
    }
    std::size_t kept = first;
    for (std::size_t i = first; i < out.blobs.size(); ++i) {
      ColourBlob& blob = out.blobs[i];
      if (static_cast<int>(blob.pixels.size()) < options_.min_blob_pixels) {
        for (std::int32_t p : blob.pixels) out.label[static_cast<std::size_t>(p)] = -1;
        continue;
      }
      blob.colour = k;
      if (kept != i) out.blobs[kept] = std::move(blob);
      ++kept;
    }
    out.blobs.resize(kept);
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
      const double angle = hue_angle_deg(a.rgb, b.rgb);
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
  std::vector<KnownColour> out;
  for (const auto& [cls, rgb] : class_colours(s)) out.push_back({cls, rgb, true});
  for (KnownColour& k : backdrop_colours(s)) out.push_back(std::move(k));
  return out;
}

std::vector<KnownColour> backdrop_colours(const world::Scenario& s) {
  std::vector<KnownColour> out;
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
