// Cameras in scenario files: the defaults of each mount, every field read as written,
// to_yaml() and back giving the same cameras (world/compare.hpp, which also sees a
// change), and the default cameras of a scenario without any: the overhead one sees
// every corner of every region (checked by projecting through its axes) and is valid,
// in a hand-written scene and in 200 generated ones (2-5 regions at random places,
// 1-8 blocks, 0-2 trays).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rtamp/world/compare.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::world {
namespace {

const char* kScene =
    "name: t\n"
    "regions:\n"
    "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36]}\n"
    "  - {name: r2, center: [0.40, -0.32, 0], size: [0.36, 0.36]}\n"
    "objects:\n"
    "  - {name: o1, position: [0.40, 0.32, 0]}\n"
    "task: F p1\n"
    "propositions: {p1: \"o1 in r2\"}\n";

TEST(CameraIo, FieldsDefaultsAndRoundTrip) {
  const std::string text = std::string(kScene) +
                           "cameras:\n"
                           "  - {name: top, position: [0.4, 0, 1.2], look_at: [0.4, 0], resolution: [320, 200],\n"
                           "     fov: 50, range: [0.2, 2.5], rate: 30, noise: {a: 0.002, b: 0, quantum_mm: 0.5,\n"
                           "     edge_dropout: 1}}\n"
                           "  - {name: grip, mount: wrist}\n";
  const Scenario s = parse_scenario(text, "t.yaml");
  ASSERT_EQ(s.cameras.size(), 2u);
  const Camera& top = s.cameras[0];
  EXPECT_EQ(top.mount, Camera::Mount::Fixed);
  EXPECT_EQ(top.width, 320);
  EXPECT_EQ(top.height, 200);
  EXPECT_EQ(top.fovy, 50);
  EXPECT_EQ(top.near, 0.2);
  EXPECT_EQ(top.far, 2.5);
  EXPECT_EQ(top.rate, 30);
  EXPECT_EQ(top.noise.a, 0.002);
  EXPECT_EQ(top.noise.quantum_mm, 0.5);
  EXPECT_EQ(top.noise.edge_dropout, 1);
  EXPECT_EQ(top.look_at, (Vec3{0.4, 0, 0}));
  const Camera& grip = s.cameras[1];
  EXPECT_EQ(grip.mount, Camera::Mount::Wrist);
  EXPECT_EQ(grip.width, 424);
  EXPECT_EQ(grip.height, 240);
  EXPECT_EQ(grip.fovy, 58);
  EXPECT_EQ(grip.near, 0.3);
  EXPECT_NEAR(horizontal_fov(grip), 87, 2);  // the D435's depth field of view across
  const Scenario back = parse_scenario(to_yaml(s), "back.yaml");
  EXPECT_EQ(first_difference(s, back), "");
  Scenario moved = back;
  moved.cameras[0].noise.edge_dropout = 0.5;
  EXPECT_EQ(first_difference(s, moved), "cameras[0].noise.edge_dropout: 1 vs 0.5");
}

// Every corner of every region of `s` is inside the camera's image and range.
void expect_sees_every_region(const Scenario& s, const Camera& c) {
  const auto ax = fixed_camera_axes(c);
  const double kPi = 3.14159265358979323846;
  const double ty = std::tan(c.fovy / 2 * kPi / 180), tx = ty * c.width / c.height;
  for (const Region& r : s.regions)
    for (int sx : {-1, 1})
      for (int sy : {-1, 1}) {
        const Vec3 v{r.center[0] + sx * r.size[0] / 2 - c.position[0], r.center[1] + sy * r.size[1] / 2 - c.position[1],
                     -c.position[2]};
        double p[3];
        for (std::size_t i = 0; i < 3; ++i) p[i] = ax[i][0] * v[0] + ax[i][1] * v[1] + ax[i][2] * v[2];
        EXPECT_GT(p[2], c.near) << s.name << " " << r.name;
        EXPECT_LT(p[2], c.far) << s.name << " " << r.name;
        EXPECT_LT(std::abs(p[0] / p[2]), tx) << s.name << " " << r.name;
        EXPECT_LT(std::abs(p[1] / p[2]), ty) << s.name << " " << r.name;
      }
}

TEST(CameraIo, DefaultOverheadSeesEveryRegionCorner) {
  Scenario s = parse_scenario(kScene, "t.yaml");
  const std::vector<Camera> cams = cameras_of(s);
  ASSERT_EQ(cams.size(), 2u);
  const Camera& c = primary_camera(cams);
  EXPECT_EQ(c.name, "overhead");
  expect_sees_every_region(s, c);
  s.cameras = cams;  // the defaults pass the validator
  EXPECT_NO_THROW(validate(s));
}

TEST(CameraIo, DefaultOverheadSeesEveryRegionOfRandomScenes) {
  // 2-5 regions at random places, 1-8 blocks, 0-2 trays (the static scenes).
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    GeneratorOptions o;
    o.layout = GeneratorOptions::Layout::Random;
    o.regions = 2 + static_cast<int>(seed % 4);
    o.objects = 1 + static_cast<int>(seed % 8);
    o.containers = std::min(o.regions - 1, static_cast<int>(seed % 3));
    o.seed = seed;
    Scenario s = generate_scenario(o);
    const std::vector<Camera> cams = default_cameras(s);
    expect_sees_every_region(s, primary_camera(cams));
    s.cameras = cams;
    EXPECT_NO_THROW(validate(s)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace rtamp::world
