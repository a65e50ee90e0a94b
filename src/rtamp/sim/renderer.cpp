#include "rtamp/sim/renderer.hpp"

#include <png.h>
#include <sys/wait.h>

#include <cstring>

#include "rtamp/sim/egl_context.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/output_file.hpp"

namespace rtamp::sim {

struct Renderer::Impl {
  explicit Impl(int width, int height) : egl(width, height) {}
  EglContext egl;
  mjvScene scene;
  mjvOption option;
  mjvCamera camera;
  mjrContext con;
  bool scene_made = false, con_made = false;
};

Renderer::Renderer(const Simulation& sim, RenderOptions options)
    : impl_(new Impl(options.width, options.height)), sim_(sim), options_(options) {
  Impl& r = *impl_;
  auto fail = [&](const std::string& what) {
    this->~Renderer();
    throw Error("offscreen rendering unavailable: " + what);
  };
  const mjModel* m = sim_.model();
  const EglContext::Use gl(r.egl);
  if (!gl.ok()) fail("eglMakeCurrent failed");
  mjv_defaultScene(&r.scene);
  mjv_defaultOption(&r.option);
  mjv_defaultCamera(&r.camera);
  mjr_defaultContext(&r.con);
  mjv_makeScene(m, &r.scene, 2000);
  r.scene_made = true;
  // The model's offscreen buffer must hold the image.
  mjModel* mm = const_cast<mjModel*>(m);
  mm->vis.global.offwidth = std::max(mm->vis.global.offwidth, options_.width);
  mm->vis.global.offheight = std::max(mm->vis.global.offheight, options_.height);
  mjr_makeContext(m, &r.con, mjFONTSCALE_100);
  r.con_made = true;
  mjr_setBuffer(mjFB_OFFSCREEN, &r.con);
  if (r.con.currentBuffer != mjFB_OFFSCREEN) fail("MuJoCo has no offscreen buffer");
  r.scene.flags[mjRND_SHADOW] = 0;
  r.scene.flags[mjRND_REFLECTION] = 0;
  r.scene.flags[mjRND_SKYBOX] = 0;
  r.camera.type = mjCAMERA_FIXED;
  r.camera.fixedcamid = mj_name2id(m, mjOBJ_CAMERA, "overview");
  if (options_.labels) r.option.label = mjLABEL_BODY;
}

Renderer::~Renderer() {
  if (!impl_) return;
  Impl& r = *impl_;
  {
    const EglContext::Use gl(r.egl);  // free this context's GL objects, not another's
    if (r.con_made) mjr_freeContext(&r.con);
    if (r.scene_made) mjv_freeScene(&r.scene);
  }
  delete impl_;
  impl_ = nullptr;
}

void Renderer::render(std::vector<std::uint8_t>& rgb) {
  Impl& r = *impl_;
  const int w = options_.width, h = options_.height;
  const EglContext::Use gl(r.egl);
  if (!gl.ok()) throw Error("offscreen rendering: eglMakeCurrent failed");
  mjv_updateScene(sim_.model(), const_cast<mjData*>(sim_.data()), &r.option, nullptr, &r.camera, mjCAT_ALL,
                  &r.scene);
  mjrRect viewport{0, 0, w, h};
  mjr_render(viewport, &r.scene, &r.con);
  flip_.resize(static_cast<std::size_t>(w) * h * 3);
  mjr_readPixels(flip_.data(), nullptr, viewport, &r.con);
  rgb.resize(flip_.size());
  const std::size_t row = static_cast<std::size_t>(w) * 3;
  for (int y = 0; y < h; ++y)
    std::memcpy(rgb.data() + row * y, flip_.data() + row * (h - 1 - y), row);
}

bool Renderer::project(const Eigen::Vector3d& p, double& x, double& y) const {
  const mjModel* m = sim_.model();
  const mjData* d = sim_.data();
  const int cam = impl_->camera.fixedcamid;
  const mjtNum* cp = d->cam_xpos + 3 * cam;
  const mjtNum* cr = d->cam_xmat + 9 * cam;  // columns: camera x, y, z in world
  const Eigen::Vector3d v = p - Eigen::Vector3d(cp[0], cp[1], cp[2]);
  // Camera frame: x right, y up, looking along -z.
  const double cx = cr[0] * v.x() + cr[3] * v.y() + cr[6] * v.z();
  const double cy = cr[1] * v.x() + cr[4] * v.y() + cr[7] * v.z();
  const double cz = cr[2] * v.x() + cr[5] * v.y() + cr[8] * v.z();
  if (cz >= 0) return false;
  const double fovy = m->cam_fovy[cam] * 3.14159265358979323846 / 180.0;
  const double f = 0.5 * options_.height / std::tan(fovy / 2);
  x = 0.5 * options_.width + f * cx / -cz;
  y = 0.5 * options_.height - f * cy / -cz;
  return true;
}

namespace {

// A PNG of `height` rows of `row_bytes` bytes (16-bit samples big-endian, as PNG stores
// them), in memory; empty if libpng failed. Rendered RGB images (flat colours) are
// written without row filters: measured on 3-block-tray's overhead frames at zlib's
// default level, 40-44 KB in 7-8 ms a frame, against 45-47 KB in 20-30 ms with
// libpng's adaptive filtering (docs/formats.md "Camera images").
std::string png_rows(const std::uint8_t* data, std::size_t row_bytes, int width, int height, int bit_depth,
                     int colour_type, bool filters) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return {};
  }
  png_set_write_fn(
      png, &out,
      [](png_structp p, png_bytep bytes, png_size_t n) {
        static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(bytes), n);
      },
      nullptr);
  if (!filters) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bit_depth, colour_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) png_write_row(png, const_cast<png_bytep>(data + static_cast<std::size_t>(y) * row_bytes));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void write_file(const std::string& path, const std::string& png) {
  if (png.empty()) throw Error("cannot write PNG '" + path + "'");
  write_output_file(path, "the PNG file", png);  // as every output is written (util/output_file.hpp)
}

}  // namespace

std::string encode_png(const std::vector<std::uint8_t>& rgb, int width, int height) {
  if (rgb.size() != static_cast<std::size_t>(width) * height * 3)
    throw Error("a " + std::to_string(width) + "x" + std::to_string(height) + " RGB image of " +
                std::to_string(rgb.size()) + " bytes");
  std::string png = png_rows(rgb.data(), static_cast<std::size_t>(width) * 3, width, height, 8, PNG_COLOR_TYPE_RGB, false);
  if (png.empty()) throw Error("PNG encoding failed");
  return png;
}

void write_png(const std::string& path, const std::vector<std::uint8_t>& rgb, int width, int height) {
  write_file(path, png_rows(rgb.data(), static_cast<std::size_t>(width) * 3, width, height, 8, PNG_COLOR_TYPE_RGB, false));
}

void write_png16(const std::string& path, const std::vector<std::uint16_t>& gray, int width, int height) {
  std::vector<std::uint8_t> bytes(gray.size() * 2);
  for (std::size_t i = 0; i < gray.size(); ++i) {
    bytes[2 * i] = static_cast<std::uint8_t>(gray[i] >> 8);
    bytes[2 * i + 1] = static_cast<std::uint8_t>(gray[i] & 0xff);
  }
  write_file(path, png_rows(bytes.data(), static_cast<std::size_t>(width) * 2, width, height, 16, PNG_COLOR_TYPE_GRAY, true));
}

namespace {

// How an ffmpeg child ended, from pclose's status: "; ffmpeg exited with status 1".
std::string how_it_ended(int status) {
  if (status == -1) return "";
  if (WIFEXITED(status)) return "; ffmpeg exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "; ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
  return "";
}

}  // namespace

VideoWriter::VideoWriter(const std::string& path, int width, int height, int fps)
    : path_(path), width_(width), height_(height) {
  // The path is passed single-quoted; a quote inside it is escaped for the shell.
  std::string quoted = "'";
  for (char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  const std::string cmd = "ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s " + std::to_string(width) + "x" +
                          std::to_string(height) + " -r " + std::to_string(fps) +
                          " -i - -c:v libx264 -pix_fmt yuv420p " + quoted;
  pipe_ = popen(cmd.c_str(), "w");
  if (!pipe_) throw Error("cannot start ffmpeg for '" + path + "'");
}

VideoWriter::~VideoWriter() {
  if (pipe_) pclose(pipe_);
}

void VideoWriter::add(const std::vector<std::uint8_t>& rgb) {
  if (!pipe_) return;
  const std::size_t expected = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 3;
  if (rgb.size() != expected)
    throw Error("a frame of " + std::to_string(rgb.size()) + " bytes for the " + std::to_string(width_) + "x" +
                std::to_string(height_) + " video '" + path_ + "' (expected " + std::to_string(expected) + ")");
  // ffmpeg gone (bad path, not installed): a short write, an error, not SIGPIPE
  // (the rtamp CLI ignores SIGPIPE; a program that does not gets the signal).
  if (std::fwrite(rgb.data(), 1, rgb.size(), pipe_) != rgb.size()) {
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    throw Error("ffmpeg stopped reading the frames of '" + path_ + "' after " + std::to_string(frames_) + " frames" +
                how_it_ended(status) + " (is the path writable? is ffmpeg installed?)");
  }
  ++frames_;
}

void VideoWriter::close() {
  if (!pipe_) return;
  const int status = pclose(pipe_);
  pipe_ = nullptr;
  if (status != 0)
    throw Error("ffmpeg failed writing '" + path_ + "'" + how_it_ended(status) + " (is ffmpeg installed?)");
}

}  // namespace rtamp::sim
