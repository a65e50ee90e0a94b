// The cameras against independent geometry: the default fixed camera's extrinsics
// equal the axes world/camera.hpp derives from its position and look-at; every pixel
// the segmentation pass gives to a block back-projects (intrinsics, extrinsics, the
// linearised depth) to a point on that block's true box, and the pixel where a block's
// top centre projects shows that block at the depth of its top face; the wrist camera
// rides on the flange and looks along the tool axis; a rig (and a Renderer) made on one
// thread renders on any other, one after the other (`rtamp serve` builds the episode on
// its main thread and steps it on the loop's); the rig's coarser geometry leaves the
// model's quality settings and plane grids as they were; the read-back for drivers
// without GL_MESA_pack_invert gives the same images as the one with it.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <thread>

#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/renderer.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

TEST(CameraRig, FixedCameraExtrinsicsMatchLookAt) {
  const world::Scenario s = testing::three_block(true);
  Simulation sim(s);
  CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  const world::Camera& c = rig.cameras()[k];
  const auto axes = world::fixed_camera_axes(c);
  const Extrinsics e = rig.extrinsics(k);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(e.R(i, j), axes[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], 1e-9);
  const Eigen::Vector3d centre = e.to_world(Eigen::Vector3d::Zero());
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(centre[j], c.position[static_cast<std::size_t>(j)], 1e-9);
  // The look-at point lies on the optical axis: it projects to the principal point.
  const Intrinsics K = rig.intrinsics(k);
  const Eigen::Vector2d uv = K.project(e.to_camera({c.look_at[0], c.look_at[1], c.look_at[2]}));
  EXPECT_NEAR(uv.x(), K.cx, 1e-9);
  EXPECT_NEAR(uv.y(), K.cy, 1e-9);
}

TEST(CameraRig, BlockPixelsBackProjectOntoTheirBoxes) {
  const world::Scenario s = testing::three_block(true);
  Simulation sim(s);
  sim.step(50);
  CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  CameraImage im;
  rig.render(k, im, {.noise = false, .segmentation = true});
  ASSERT_EQ(im.width, 640);
  ASSERT_EQ(im.height, 480);
  for (const char* name : {"o1", "o2", "o3"}) {
    const Thing& t = sim.thing(sim.find(name));
    const Eigen::Vector3d centre = sim.position(sim.find(name));
    const double half = t.size[0] / 2, top = centre.z() + t.size[2] / 2;
    int pixels = 0, off_box = 0, on_top = 0;
    double worst = 0;
    for (int v = 0; v < im.height; ++v)
      for (int u = 0; u < im.width; ++u) {
        const std::size_t i = static_cast<std::size_t>(v) * im.width + u;
        if (im.body[i] != t.body || im.depth[i] <= 0) continue;
        ++pixels;
        const Eigen::Vector3d p = im.extrinsics.to_world(im.intrinsics.back_project(u, v, im.depth[i]));
        // Distance outside the (axis-aligned: the blocks rest unrotated) true box.
        const Eigen::Vector3d d = (p - centre).cwiseAbs() - Eigen::Vector3d(half, half, t.size[2] / 2);
        const double out = d.cwiseMax(0.0).norm();
        worst = std::max(worst, out);
        off_box += out > 0.002;
        on_top += std::abs(p.z() - top) < 0.001;
      }
    EXPECT_GT(pixels, 100) << name;
    EXPECT_EQ(off_box, 0) << name << ": worst " << worst << " m off its box";
    EXPECT_GT(on_top, pixels / 2) << name;
    // The top centre's pixel shows the block at the top face's depth along its ray.
    const Eigen::Vector2d uv = im.intrinsics.project(im.extrinsics.to_camera({centre.x(), centre.y(), top}));
    const int u = static_cast<int>(std::lround(uv.x())), v = static_cast<int>(std::lround(uv.y()));
    const std::size_t i = static_cast<std::size_t>(v) * im.width + u;
    EXPECT_EQ(im.body[i], t.body) << name;
    const Eigen::Vector3d ray = im.extrinsics.R.transpose() * im.intrinsics.back_project(u, v, 1.0);
    const Eigen::Vector3d eye = im.extrinsics.to_world(Eigen::Vector3d::Zero());
    const double z_expected = (top - eye.z()) / ray.z();  // camera z where the ray meets the top plane
    EXPECT_NEAR(im.depth[i], z_expected, 0.001) << name;
  }
}

TEST(CameraRig, WristCameraRidesOnTheFlange) {
  const world::Scenario s = testing::three_block(true);
  Simulation sim(s);
  sim.step(10);
  CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("wrist", {});
  const world::Camera& c = rig.cameras()[k];
  const Extrinsics e = rig.extrinsics(k);
  const int body = mj_name2id(sim.model(), mjOBJ_BODY, "ur5:flange");
  ASSERT_GE(body, 0);
  const mjtNum* p = sim.data()->xpos + 3 * body;
  const mjtNum* R = sim.data()->xmat + 9 * body;  // row-major, columns = flange axes
  Eigen::Matrix3d flange;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) flange(i, j) = R[3 * i + j];
  const Eigen::Vector3d expected_eye =
      Eigen::Vector3d(p[0], p[1], p[2]) + flange * Eigen::Vector3d(c.position[0], c.position[1], c.position[2]);
  EXPECT_LT((e.to_world(Eigen::Vector3d::Zero()) - expected_eye).norm(), 1e-9);
  EXPECT_LT((e.R.row(2).transpose() - flange.col(2)).norm(), 1e-9);  // optical axis = tool axis
  EXPECT_LT((e.R.row(0).transpose() - flange.col(0)).norm(), 1e-9);  // image x = flange x
  CameraImage im;
  rig.render(k, im);
  EXPECT_EQ(im.width, 424);
  EXPECT_EQ(im.height, 240);
}

TEST(CameraRig, RendersOnWhicheverThreadRenders) {
  const world::Scenario s = testing::three_block(false);
  Simulation sim(s);
  CameraRig rig(sim, world::cameras_of(s));
  Renderer overview(sim, {.width = 320, .height = 240});
  const std::size_t k = rig.index("overhead", {});
  CameraImage first, again;
  std::vector<std::uint8_t> picture;
  std::string error;
  const auto on_another_thread = [&](const std::function<void()>& f) {
    std::thread([&] {
      try {
        f();
      } catch (const std::exception& e) {
        error = e.what();
      }
    }).join();
  };
  on_another_thread([&] { rig.render(k, first, {.noise = false, .segmentation = false}); });
  ASSERT_EQ(error, "");
  on_another_thread([&] { overview.render(picture); });
  ASSERT_EQ(error, "");
  rig.render(k, again, {.noise = false, .segmentation = false});  // and back on this one
  on_another_thread([&] { overview.render(picture); });
  ASSERT_EQ(error, "");
  ASSERT_EQ(first.rgb.size(), static_cast<std::size_t>(640) * 480 * 3);
  EXPECT_EQ(first.rgb, again.rgb);  // the same picture from either thread
  EXPECT_EQ(picture.size(), static_cast<std::size_t>(320) * 240 * 3);
}

TEST(CameraRig, LeavesTheModelsRenderSettingsAsTheyWere) {
  const world::Scenario s = testing::three_block(true);
  Simulation sim(s);
  const mjModel* m = sim.model();
  const auto quality = m->vis.quality;
  const std::vector<mjtNum> sizes(m->geom_size, m->geom_size + 3 * m->ngeom);
  {
    CameraRig rig(sim, world::cameras_of(s));
    EXPECT_NE(m->vis.quality.numslices, 0);
  }
  EXPECT_EQ(std::memcmp(&m->vis.quality, &quality, sizeof quality), 0);
  EXPECT_EQ(std::vector<mjtNum>(m->geom_size, m->geom_size + 3 * m->ngeom), sizes);
}

TEST(CameraRig, BothReadBackPathsGiveTheSameImages) {
  const world::Scenario s = testing::three_block(true);
  Simulation sim(s);
  CameraRig rig(sim, world::cameras_of(s));
  if (!rig.pack_invert()) GTEST_SKIP() << "the driver has no GL_MESA_pack_invert: one path only";
  for (const char* name : {"overhead", "wrist"}) {
    const std::size_t k = rig.index(name, {});
    CameraImage top_first, turned;
    rig.render(k, top_first, {.noise = false, .segmentation = true});
    rig.set_pack_invert(false);
    rig.render(k, turned, {.noise = false, .segmentation = true});
    rig.set_pack_invert(true);
    ASSERT_FALSE(top_first.rgb.empty());
    EXPECT_EQ(top_first.rgb, turned.rgb) << name;
    EXPECT_EQ(top_first.depth, turned.depth) << name;
    EXPECT_EQ(top_first.body, turned.body) << name;
    // Not symmetric top to bottom: a flipped read would differ.
    const std::size_t row = static_cast<std::size_t>(top_first.width) * 3;
    EXPECT_NE(std::vector<std::uint8_t>(top_first.rgb.begin(), top_first.rgb.begin() + static_cast<std::ptrdiff_t>(row)),
              std::vector<std::uint8_t>(top_first.rgb.end() - static_cast<std::ptrdiff_t>(row), top_first.rgb.end()))
        << name;
  }
}

TEST(CameraRig, UnknownCameraIsNamed) {
  const world::Scenario s = testing::three_block(false);
  Simulation sim(s);
  CameraRig rig(sim, world::cameras_of(s));
  try {
    rig.index("nope", SourceLocation{"--camera", 1, 1});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown camera 'nope' (cameras: overhead, wrist)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rtamp::sim
