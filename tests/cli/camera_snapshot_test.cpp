// `rtamp sim --camera NAME --snapshot/--depth/--segmentation` writes the camera's
// images at its resolution (read back with libpng: RGB 8-bit, depth 16-bit grey in
// mm, segmentation RGB); a camera 1 m above the table looking straight down reads
// 1000 mm at its image centre (within its noise), and `--snapshot` alone still
// writes the overview picture at --width x --height.
#include <gtest/gtest.h>
#include <png.h>

#include <cstring>

#include "run_cli.hpp"

namespace rtamp::cli::testing {
namespace {

struct Png {
  int width = 0, height = 0, bit_depth = 0, colour = 0;
  std::vector<std::uint8_t> data;  // rows as stored
};

Png read_png(const std::string& path) {
  Png p;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return p;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(f);
    return Png{};
  }
  png_init_io(png, f);
  png_read_info(png, info);
  p.width = static_cast<int>(png_get_image_width(png, info));
  p.height = static_cast<int>(png_get_image_height(png, info));
  p.bit_depth = png_get_bit_depth(png, info);
  p.colour = png_get_color_type(png, info);
  const std::size_t row = png_get_rowbytes(png, info);
  p.data.resize(row * static_cast<std::size_t>(p.height));
  for (int y = 0; y < p.height; ++y) png_read_row(png, p.data.data() + row * static_cast<std::size_t>(y), nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(f);
  return p;
}

TEST(CameraSnapshot, WritesTheCamerasImages) {
  const auto dir = scratch();
  const std::string rgb = (dir / "rgb.png").string(), depth = (dir / "depth.png").string(),
                    seg = (dir / "seg.png").string(), overview = (dir / "overview.png").string();
  const std::string scenario = write_file(
      "cams.yaml",
      "name: cams\n"
      "regions:\n"
      "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36]}\n"
      "  - {name: r2, center: [0.40, -0.32, 0], size: [0.36, 0.36]}\n"
      "objects:\n"
      "  - {name: o1, position: [0.40, 0.32, 0]}\n"
      "propositions: {p: \"o1 in r2\"}\n"
      "task: F p\n"
      "cameras:\n"
      "  - {name: down, position: [0.4, 0, 1.0], look_at: [0.4, 0, 0], resolution: [320, 240]}\n");
  const Result r = run("sim '" + scenario + "' --camera down --snapshot '" + rgb + "' --depth '" + depth +
                       "' --segmentation '" + seg + "'");
  ASSERT_EQ(r.rc, 0) << r.err;
  const Png a = read_png(rgb), d = read_png(depth), s = read_png(seg);
  EXPECT_EQ(a.width, 320);
  EXPECT_EQ(a.height, 240);
  EXPECT_EQ(a.bit_depth, 8);
  EXPECT_EQ(a.colour, PNG_COLOR_TYPE_RGB);
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.colour, PNG_COLOR_TYPE_RGB);
  ASSERT_EQ(d.width, 320);
  ASSERT_EQ(d.height, 240);
  EXPECT_EQ(d.bit_depth, 16);
  EXPECT_EQ(d.colour, PNG_COLOR_TYPE_GRAY);
  // The centre pixel: the table top 1 m below (noise σ = 0.5 + 1.5 mm there).
  const std::size_t k = (120u * 320u + 160u) * 2;
  const int mm = d.data[k] * 256 + d.data[k + 1];
  EXPECT_NEAR(mm, 1000, 10);
  // Without --camera: the overview picture, as before.
  const Result o = run("sim 3-block-tray --snapshot '" + overview + "' --width 320 --height 240");
  ASSERT_EQ(o.rc, 0) << o.err;
  const Png v = read_png(overview);
  EXPECT_EQ(v.width, 320);
  EXPECT_EQ(v.height, 240);
}

}  // namespace
}  // namespace rtamp::cli::testing
