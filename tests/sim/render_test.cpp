// A snapshot is a valid PNG (read back with libpng) in which the blocks and the arm are
// visible: the pixel where each block's top centre projects has the block colour, and
// the pixel where the upper arm projects has the arm's grey, not the table's colour.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "rtamp/sim/renderer.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

std::vector<std::uint8_t> read_png(const std::string& path, int& w, int& h) {
  std::vector<std::uint8_t> out;
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str())) return out;
  img.format = PNG_FORMAT_RGB;
  out.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.data(), 0, nullptr)) out.clear();
  w = static_cast<int>(img.width), h = static_cast<int>(img.height);
  return out;
}

TEST(SimRender, SnapshotShowsArmAndBlocks) {
  Simulation sim(testing::three_block(true));
  sim.step(50);
  Renderer r(sim, {320, 240, false});
  std::vector<std::uint8_t> rgb;
  r.render(rgb);
  const auto path = (std::filesystem::temp_directory_path() / "rtamp_sim_render_test.png").string();
  write_png(path, rgb, r.width(), r.height());
  int w = 0, h = 0;
  auto back = read_png(path, w, h);
  ASSERT_EQ(w, 320);
  ASSERT_EQ(h, 240);
  ASSERT_EQ(back, rgb);
  auto pixel = [&](const Eigen::Vector3d& p) {
    double x, y;
    EXPECT_TRUE(r.project(p, x, y));
    const int ix = static_cast<int>(x), iy = static_cast<int>(y);
    EXPECT_TRUE(ix >= 0 && ix < w && iy >= 0 && iy < h);
    const std::size_t k = (static_cast<std::size_t>(iy) * w + ix) * 3;
    return std::array<int, 3>{back[k], back[k + 1], back[k + 2]};
  };
  for (const char* n : {"o1", "o2", "o3"}) {
    auto c = pixel(sim.position(sim.find(n)) + Eigen::Vector3d(0, 0, 0.02));
    // Blocks are red: red dominates clearly.
    EXPECT_GT(c[0], 90) << n;
    EXPECT_GT(c[0], c[1] + 40) << n;
    EXPECT_GT(c[0], c[2] + 40) << n;
  }
  // Upper arm: the centre of link 2's capsule (grey, not the near-white table or floor).
  const int g = mj_name2id(sim.model(), mjOBJ_GEOM, "ur5:link2/x");
  ASSERT_GE(g, 0);
  const mjtNum* gp = sim.data()->geom_xpos + 3 * g;
  auto arm = pixel(Eigen::Vector3d(gp[0], gp[1], gp[2]));
  EXPECT_LT(arm[0] + arm[1] + arm[2], 3 * 215);
  if (!std::getenv("RTAMP_KEEP_PNG")) std::filesystem::remove(path);
}

}  // namespace
}  // namespace rtamp::sim
