#include "rtamp/sim/camera_snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "rtamp/sim/renderer.hpp"
#include "rtamp/sim/scene_style.hpp"

namespace rtamp::sim {

namespace {

std::array<std::uint8_t, 3> bytes(const std::array<double, 3>& c) {
  auto b = [](double v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5); };
  return {b(c[0]), b(c[1]), b(c[2])};
}

// A body that is not a thing: a hue stepped by the golden angle from its id.
std::array<std::uint8_t, 3> body_colour(int body) {
  const double h = std::fmod(body * 0.6180339887498949, 1.0) * 6;
  const int i = static_cast<int>(h);
  const double f = h - i, p = 0.25, q = 1 - 0.75 * f, t = 0.25 + 0.75 * f;
  const std::array<std::array<double, 3>, 6> rgb{{{1, t, p}, {q, 1, p}, {p, 1, t}, {p, q, 1}, {t, p, 1}, {1, p, q}}};
  return bytes(rgb[static_cast<std::size_t>(i % 6)]);
}

}  // namespace

void write_camera_snapshot(CameraRig& rig, std::size_t camera, const Simulation& sim, const CameraFiles& files) {
  CameraImage image;
  CameraPasses passes;
  passes.segmentation = !files.segmentation.empty();
  rig.render(camera, image, passes);
  if (!files.rgb.empty()) write_png(files.rgb, image.rgb, image.width, image.height);
  if (!files.depth.empty()) {
    std::vector<std::uint16_t> mm(image.depth.size());
    for (std::size_t i = 0; i < mm.size(); ++i)
      mm[i] = static_cast<std::uint16_t>(std::min(65535.0, std::round(image.depth[i] * 1000.0)));
    write_png16(files.depth, mm, image.width, image.height);
  }
  if (!files.segmentation.empty()) {
    std::map<int, std::array<std::uint8_t, 3>> colour{{0, {70, 70, 70}}};  // the world body: table, regions
    for (const Thing& t : sim.things()) colour[t.body] = bytes(class_colour(sim.scenario(), t.cls));
    std::vector<std::uint8_t> rgb(image.body.size() * 3, 0);
    for (std::size_t i = 0; i < image.body.size(); ++i) {
      const int b = image.body[i];
      if (b < 0) continue;
      auto it = colour.find(b);
      const auto c = it != colour.end() ? it->second : body_colour(b);
      std::copy(c.begin(), c.end(), rgb.begin() + static_cast<std::ptrdiff_t>(3 * i));
    }
    write_png(files.segmentation, rgb, image.width, image.height);
  }
}

}  // namespace rtamp::sim
