#include "rtamp/sim/class_colours.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

#include "rtamp/sim/colour_segmentation.hpp"

namespace rtamp::sim {

namespace {

struct NamedColour {
  const char* name;
  Rgb rgb;
};

// Common colour names, as the scene draws them (no channel above 0.9: a lit top face
// stays below 255, which keeps its hue; docs/perception.md). Greys have no hue.
constexpr NamedColour kNamed[] = {
    {"red", {0.85, 0.15, 0.12}},    {"crimson", {0.80, 0.10, 0.30}}, {"maroon", {0.55, 0.10, 0.10}},
    {"orange", {0.90, 0.50, 0.08}}, {"brown", {0.55, 0.36, 0.20}},   {"gold", {0.85, 0.65, 0.10}},
    {"yellow", {0.90, 0.80, 0.10}}, {"olive", {0.50, 0.50, 0.10}},   {"lime", {0.55, 0.85, 0.10}},
    {"green", {0.20, 0.70, 0.20}},  {"teal", {0.10, 0.60, 0.55}},    {"turquoise", {0.15, 0.80, 0.70}},
    {"cyan", {0.10, 0.75, 0.85}},   {"blue", {0.15, 0.30, 0.85}},    {"navy", {0.10, 0.15, 0.50}},
    {"indigo", {0.30, 0.15, 0.65}}, {"violet", {0.60, 0.30, 0.85}},  {"purple", {0.55, 0.20, 0.70}},
    {"magenta", {0.85, 0.15, 0.70}}, {"pink", {0.85, 0.35, 0.55}},
};
constexpr int kNamedWindow = 10;  // degrees of hue a named colour may move (see near_named)

constexpr Rgb kBlockRed{0.85, 0.15, 0.12};
constexpr Rgb kTrayWood{0.55, 0.36, 0.20};

// A hue at `p` degrees along the boundary of the chroma directions, red -> yellow ->
// green -> cyan -> blue -> magenta -> red (45 degrees each, as the segmentation measures
// within one leg), drawn with channels between `lo` and `hi`.
Rgb hue_at(double p, double lo = 0.12, double hi = 0.85) {
  p = std::fmod(std::fmod(p, 270.0) + 270.0, 270.0);
  const int leg = static_cast<int>(std::floor(p / 45)) % 6;
  const double f = (p - 45.0 * std::floor(p / 45)) * std::numbers::pi / 180;
  const double up = std::tan(f), down = std::tan(std::numbers::pi / 4 - f);
  std::array<double, 3> d{};
  switch (leg) {
    case 0: d = {1, up, 0}; break;
    case 1: d = {down, 1, 0}; break;
    case 2: d = {0, 1, up}; break;
    case 3: d = {0, down, 1}; break;
    case 4: d = {up, 0, 1}; break;
    default: d = {1, 0, down}; break;
  }
  return {lo + (hi - lo) * d[0], lo + (hi - lo) * d[1], lo + (hi - lo) * d[2]};
}

// Where a colour with a hue lies along hue_at's path (its inverse, up to value).
double path_position(const Rgb& c) {
  const double lo = std::min({c[0], c[1], c[2]}), m = std::max({c[0], c[1], c[2]}) - lo;
  const double r = (c[0] - lo) / m, g = (c[1] - lo) / m, b = (c[2] - lo) / m;
  auto deg = [](double x) { return std::atan(x) * 180 / std::numbers::pi; };
  if (b == 0 && r == 1) return deg(g);
  if (b == 0 && g == 1) return 90 - deg(r);
  if (r == 0 && g == 1) return 90 + deg(b);
  if (r == 0 && b == 1) return 180 - deg(g);
  if (g == 0 && b == 1) return 180 + deg(r);
  return 270 - deg(b);
}

double nearest(const Rgb& c, const std::vector<Rgb>& others) {
  double best = 90;
  for (const Rgb& o : others) best = std::min(best, hue_angle_deg(c, o));
  return best;
}

// The free hue for the next class: among hues every 3 degrees, one at least kMinHueApart
// from the backdrop's hues if any such is also kMinHueApart from every taken colour; of
// those the farthest from the taken colours (the first of equals).
Rgb free_hue(const std::vector<Rgb>& taken, const std::vector<Rgb>& backdrop) {
  Rgb best{};
  std::tuple<bool, double> best_key{false, -1};
  for (int k = 0; k < 90; ++k) {
    const Rgb c = hue_at(3.0 * k);
    const double d = nearest(c, taken);
    const bool clear = d >= kMinHueApart && nearest(c, backdrop) >= kMinHueApart;
    const std::tuple<bool, double> key{clear, d};
    if (key > best_key) best_key = key, best = c;
  }
  return best;
}

// A class's named colour: `nominal`, or a hue within kNamedWindow of it (at its value)
// that is kMinHueApart from every taken colour; of those the clearest of the backdrop
// (up to kMinHueApart), then the nearest the nominal. None if every one is taken.
std::optional<Rgb> near_named(const Rgb& nominal, const std::vector<Rgb>& taken, const std::vector<Rgb>& backdrop) {
  const double p0 = path_position(nominal);
  const double lo = std::min({nominal[0], nominal[1], nominal[2]}), hi = std::max({nominal[0], nominal[1], nominal[2]});
  std::optional<Rgb> best;
  std::tuple<double, int> best_key{-1, 0};
  for (int k = 0; k <= 2 * kNamedWindow; ++k) {
    const int dk = (k + 1) / 2 * (k % 2 ? 1 : -1);  // 0, +1, -1, +2, -2, ...
    const Rgb c = dk == 0 ? nominal : hue_at(p0 + dk, lo, hi);
    if (nearest(c, taken) < kMinHueApart) continue;
    const std::tuple<double, int> key{std::min(nearest(c, backdrop), kMinHueApart), -std::abs(dk)};
    if (key > best_key) best_key = key, best = c;
  }
  return best;
}

// The classes `s` names, in declaration order (see the header).
std::vector<std::string> declared_classes(const world::Scenario& s) {
  struct First {
    int line, column;
    std::size_t seq;
    std::string cls;
  };
  std::vector<First> firsts;
  auto note = [&](const std::string& cls, const SourceLocation& where) {
    if (cls.empty()) return;
    for (const First& f : firsts)
      if (f.cls == cls) return;
    firsts.push_back({where.line, where.column, firsts.size(), cls});
  };
  for (const auto& o : s.objects) note(o.cls, o.where);
  for (const auto& c : s.containers) note(c.cls, c.where);
  for (const auto& i : s.interventions) note(i.cls, i.where);
  std::stable_sort(firsts.begin(), firsts.end(), [](const First& a, const First& b) {
    return std::tie(a.line, a.column) < std::tie(b.line, b.column);
  });
  std::vector<std::string> out;
  for (const First& f : firsts) out.push_back(f.cls);
  return out;
}

}  // namespace

const Rgb* named_colour(const std::string& name) {
  for (const NamedColour& n : kNamed)
    if (name == n.name) return &n.rgb;
  return nullptr;
}

const Rgb* colour_named_in(const std::string& cls) {
  // Words: runs of letters, split also where a capital follows a small letter (camelCase).
  std::vector<std::string> words(1);
  for (std::size_t i = 0; i < cls.size(); ++i) {
    const auto c = static_cast<unsigned char>(cls[i]);
    const bool split = !std::isalpha(c) ||
                       (std::isupper(c) && i > 0 && std::islower(static_cast<unsigned char>(cls[i - 1])));
    if (split && !words.back().empty()) words.emplace_back();
    if (std::isalpha(c)) words.back() += static_cast<char>(std::tolower(c));
  }
  for (const std::string& w : words)
    if (const Rgb* rgb = named_colour(w)) return rgb;
  return nullptr;
}

std::map<std::string, Rgb> class_colours(const world::Scenario& s, const std::string& extra) {
  std::vector<std::string> order = declared_classes(s);
  for (const char* d : {"block", "tray"})
    if (std::find(order.begin(), order.end(), d) == order.end()) order.push_back(d);
  if (!extra.empty() && std::find(order.begin(), order.end(), extra) == order.end()) order.push_back(extra);

  std::map<std::string, Rgb> out;
  std::vector<Rgb> taken;
  std::vector<std::string> free;  // classes that take a free hue, in this order
  auto take = [&](const std::string& cls, const Rgb& rgb) {
    out[cls] = rgb;
    taken.push_back(rgb);
  };
  auto offer = [&](const std::string& cls, const Rgb& rgb) {  // a default: kept if it collides with none before it
    if (nearest(rgb, taken) >= kMinHueApart) take(cls, rgb);
    else free.push_back(cls);
  };
  auto pending = [&](const std::string& cls) {
    return !out.count(cls) && std::find(free.begin(), free.end(), cls) == free.end();
  };
  std::vector<Rgb> backdrop;
  for (const KnownColour& k : backdrop_colours(s))
    if (chroma_span(k.rgb) >= 0.1) backdrop.push_back(k.rgb);
  for (const world::ClassColour& c : s.colours) take(c.cls, c.rgb);
  for (const std::string& cls : order)
    if (pending(cls))
      if (const Rgb* rgb = colour_named_in(cls)) {
        if (const std::optional<Rgb> c = near_named(*rgb, taken, backdrop)) take(cls, *c);
        else free.push_back(cls);
      }
  if (pending("block")) offer("block", kBlockRed);
  if (pending("tray")) offer("tray", kTrayWood);
  for (const std::string& cls : order)
    if (pending(cls)) free.push_back(cls);
  for (const std::string& cls : free) take(cls, free_hue(taken, backdrop));
  return out;
}

}  // namespace rtamp::sim
