#include "rtamp/sim/camera_rig.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <EGL/egl.h>

#include "rtamp/sim/depth_noise.hpp"
#include "rtamp/sim/egl_context.hpp"
#include "rtamp/sim/mjcf_builder.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::sim {

namespace {

int max_width(const std::vector<world::Camera>& cs) {
  int w = world::kMinCameraPixels;
  for (const auto& c : cs) w = std::max(w, c.width);
  return w;
}
int max_height(const std::vector<world::Camera>& cs) {
  int h = world::kMinCameraPixels;
  for (const auto& c : cs) h = std::max(h, c.height);
  return h;
}

// Rows of a bottom-up image of `row` elements each, top row first, into `out` (resized).
template <class T>
void flip_rows(const std::vector<T>& in, std::vector<T>& out, std::size_t row, int height) {
  out.resize(in.size());
  for (int y = 0; y < height; ++y)
    std::memcpy(out.data() + row * y, in.data() + row * (height - 1 - y), row * sizeof(T));
}

// The depth-stencil buffer `d` (24 bits of depth d24 over 8 of stencil; bottom row first
// if `flip`) as metres along the optical axis, top row first: with d = d24 / (2^24 - 1),
// z = n / (1 - d (1 - n/f)) (MuJoCo's clip planes), 0 outside [near, far].
void linear_depth(const std::vector<std::uint32_t>& d, std::vector<float>& out, int width, int height, bool flip,
                  double zn, double zf, double near, double far) {
  out.resize(d.size());
  const double k = (1 - zn / zf) / 16777215.0;
  const auto w = static_cast<std::size_t>(width);
  for (int y = 0; y < height; ++y) {
    const std::uint32_t* in = d.data() + w * static_cast<std::size_t>(flip ? height - 1 - y : y);
    float* o = out.data() + w * static_cast<std::size_t>(y);
    for (std::size_t x = 0; x < w; ++x) {  // branch-free: vectorised
      const double z = zn / (1 - static_cast<double>(static_cast<std::int32_t>(in[x] >> 8)) * k);
      o[x] = ((z >= near) & (z <= far)) ? static_cast<float>(z) : 0.0f;
    }
  }
}

// The OpenGL calls the read-back makes itself, from EGL (the library links no OpenGL).
// MuJoCo's offscreen depth-stencil buffer (GL_DEPTH24_STENCIL8) is read as it is stored,
// which costs less than converted to floats by the driver; with GL_MESA_pack_invert (Mesa
// has it) the images come top row first, with no copy to turn them.
struct Gl {
  void (*read_pixels)(int, int, int, int, unsigned, unsigned, void*) = nullptr;
  void (*pixel_store)(unsigned, int) = nullptr;  // null: no GL_MESA_pack_invert
  bool invert = false;                           // read top row first (pixel_store not null)
};
constexpr unsigned kDepthStencil = 0x84F9, kUnsignedInt24_8 = 0x84FA;  // GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8
constexpr unsigned kRgb = 0x1907, kUnsignedByte = 0x1401;               // GL_RGB, GL_UNSIGNED_BYTE
constexpr unsigned kPackAlignment = 0x0D05, kPackInvertMesa = 0x8758, kExtensions = 0x1F03;

Gl load_gl() {  // with the context current
  Gl gl;
  gl.read_pixels = reinterpret_cast<decltype(gl.read_pixels)>(eglGetProcAddress("glReadPixels"));
  if (!gl.read_pixels) throw Error("offscreen rendering unavailable: no glReadPixels");
  const auto get_string = reinterpret_cast<const unsigned char* (*)(unsigned)>(eglGetProcAddress("glGetString"));
  const char* extensions = get_string ? reinterpret_cast<const char*>(get_string(kExtensions)) : nullptr;
  if (extensions && std::strstr(extensions, "GL_MESA_pack_invert"))
    gl.pixel_store = reinterpret_cast<decltype(gl.pixel_store)>(eglGetProcAddress("glPixelStorei"));
  gl.invert = gl.pixel_store != nullptr;
  return gl;
}

// The geometry the camera renders: round shapes as 12-gons (MuJoCo's default is 28; an
// arm link 6 cm across is off by at most 2 mm at its rim), a box face or a plane as
// one quad (flat faces under the scene's directional lights). The render of a 640x480
// frame costs 0.57x what it did with MuJoCo's defaults (docs/benchmarks.md).
constexpr int kRenderSlices = 12, kRenderStacks = 6;

}  // namespace

struct CameraRig::Impl {
  Impl(int width, int height) : egl(width, height) {}
  EglContext egl;
  mjvScene scene;
  mjvOption option;
  mjvCamera camera;
  mjrContext con;
  bool scene_made = false, con_made = false;
  // Read-back and intermediate images, kept between frames (no allocation per frame).
  std::vector<std::uint8_t> rgb, seg;
  std::vector<std::uint32_t> depth;
  std::vector<float> clean;
  Gl gl;
};

CameraRig::CameraRig(const Simulation& sim, std::vector<world::Camera> cameras, std::uint64_t seed)
    : sim_(sim), cameras_(std::move(cameras)), rng_(seed) {
  const mjModel* m = sim_.model();
  for (const auto& c : cameras_) {
    const int id = mj_name2id(m, mjOBJ_CAMERA, mujoco_camera_name(c.name).c_str());
    if (id < 0) throw Error("camera '" + c.name + "' is not in the simulation's model");
    mj_camera_.push_back(id);
  }
  const int w = max_width(cameras_), h = max_height(cameras_);
  if (m->vis.global.offwidth < w || m->vis.global.offheight < h)
    throw Error("the model's offscreen buffer is smaller than the cameras' images");
  impl_ = std::make_unique<Impl>(w, h);
  Impl& r = *impl_;
  const EglContext::Use gl(r.egl);
  if (!gl.ok()) throw Error("offscreen rendering unavailable: eglMakeCurrent failed");
  mjv_defaultScene(&r.scene);
  mjv_defaultOption(&r.option);
  mjv_defaultCamera(&r.camera);
  mjr_defaultContext(&r.con);
  mjv_makeScene(m, &r.scene, 2000);
  r.scene_made = true;
  // The context's geometry is baked when it is made, from the model's quality settings
  // and plane grids: it is made with the camera's (kRenderSlices), then the model's are
  // put back.
  mjModel* mm = const_cast<mjModel*>(m);
  const auto quality = mm->vis.quality;
  std::vector<mjtNum> grid;
  for (int g = 0; g < m->ngeom; ++g)
    if (m->geom_type[g] == mjGEOM_PLANE) {
      grid.push_back(mm->geom_size[3 * g + 2]);
      mm->geom_size[3 * g + 2] = 2 * std::max(mm->geom_size[3 * g], mm->geom_size[3 * g + 1]);
    }
  // No multisampling: a pixel shows one surface, so its depth, colour and segment
  // belong to the same point (as a depth sensor's do).
  mm->vis.quality.offsamples = 0;
  mm->vis.quality.numslices = kRenderSlices;
  mm->vis.quality.numstacks = kRenderStacks;
  mm->vis.quality.numquads = 1;
  mjr_makeContext(m, &r.con, mjFONTSCALE_100);
  mm->vis.quality = quality;
  for (int g = 0, i = 0; g < m->ngeom; ++g)
    if (m->geom_type[g] == mjGEOM_PLANE) mm->geom_size[3 * g + 2] = grid[static_cast<std::size_t>(i++)];
  r.con_made = true;
  mjr_setBuffer(mjFB_OFFSCREEN, &r.con);
  if (r.con.currentBuffer != mjFB_OFFSCREEN) throw Error("offscreen rendering unavailable: no offscreen buffer");
  r.gl = load_gl();
  r.scene.flags[mjRND_SHADOW] = 0;
  r.scene.flags[mjRND_REFLECTION] = 0;
  r.scene.flags[mjRND_SKYBOX] = 0;
  r.camera.type = mjCAMERA_FIXED;
  for (int g = 0; g < mjNGROUP; ++g) r.option.sitegroup[g] = 0;  // sites are markers, not matter
}

CameraRig::~CameraRig() {
  if (!impl_) return;
  Impl& r = *impl_;
  const EglContext::Use gl(r.egl);  // free this context's GL objects, not another's
  if (r.con_made) mjr_freeContext(&r.con);
  if (r.scene_made) mjv_freeScene(&r.scene);
}

std::size_t CameraRig::index(const std::string& name, const SourceLocation& where) const {
  const world::Camera& c = world::find_camera(cameras_, name, where);
  return static_cast<std::size_t>(&c - cameras_.data());
}

Intrinsics CameraRig::intrinsics(std::size_t camera) const {
  const world::Camera& c = cameras_.at(camera);
  Intrinsics k;
  k.width = c.width;
  k.height = c.height;
  k.fy = 0.5 * c.height / std::tan(c.fovy / 2 * 3.14159265358979323846 / 180);
  k.fx = k.fy;  // square pixels
  k.cx = 0.5 * c.width - 0.5;  // OpenGL's pixel centres are at +0.5
  k.cy = 0.5 * c.height - 0.5;
  return k;
}

Extrinsics CameraRig::extrinsics(std::size_t camera) const {
  const int id = mj_camera_.at(camera);
  const mjData* d = sim_.data();
  const mjtNum* p = d->cam_xpos + 3 * id;
  const mjtNum* x = d->cam_xmat + 9 * id;  // row-major; columns: MuJoCo's camera x, y, z in the world
  Extrinsics e;
  for (int j = 0; j < 3; ++j) {
    e.R(0, j) = x[3 * j + 0];   // OpenCV x = MuJoCo x
    e.R(1, j) = -x[3 * j + 1];  // OpenCV y = -MuJoCo y
    e.R(2, j) = -x[3 * j + 2];  // OpenCV z = -MuJoCo z
  }
  e.t = -e.R * Eigen::Vector3d(p[0], p[1], p[2]);
  return e;
}

void CameraRig::add_noise(std::size_t camera, CameraImage& image) {
  const world::Camera& c = cameras_.at(camera);
  std::vector<float>& clean = impl_->clean;
  clean.swap(image.depth);  // buffers trade places: no allocation once both have the size
  apply_depth_noise(clean, image.depth, c.width, c.height, c.noise, rng_);
}

bool CameraRig::pack_invert() const { return impl_->gl.invert; }

void CameraRig::set_pack_invert(bool on) { impl_->gl.invert = on && impl_->gl.pixel_store; }

void CameraRig::render(std::size_t camera, CameraImage& out, CameraPasses passes) {
  const world::Camera& c = cameras_.at(camera);
  Impl& r = *impl_;
  const EglContext::Use gl(r.egl);
  if (!gl.ok()) throw Error("offscreen rendering: eglMakeCurrent failed");
  const mjModel* m = sim_.model();
  const int w = c.width, h = c.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  r.camera.fixedcamid = mj_camera_[camera];
  mjv_updateScene(m, const_cast<mjData*>(sim_.data()), &r.option, nullptr, &r.camera, mjCAT_ALL, &r.scene);
  const mjrRect viewport{0, 0, w, h};
  mjr_render(viewport, &r.scene, &r.con);
  r.depth.resize(n);
  out.rgb.resize(n * 3);
  if (r.gl.invert) {  // top row first, straight into the image
    mjr_setBuffer(mjFB_OFFSCREEN, &r.con);
    r.gl.pixel_store(kPackAlignment, 1);
    r.gl.pixel_store(kPackInvertMesa, 1);
    r.gl.read_pixels(0, 0, w, h, kRgb, kUnsignedByte, out.rgb.data());
    r.gl.read_pixels(0, 0, w, h, kDepthStencil, kUnsignedInt24_8, r.depth.data());
    r.gl.pixel_store(kPackInvertMesa, 0);
  } else {
    r.rgb.resize(n * 3);
    mjr_readPixels(r.rgb.data(), nullptr, viewport, &r.con);  // leaves the offscreen buffer bound for reading
    r.gl.read_pixels(0, 0, w, h, kDepthStencil, kUnsignedInt24_8, r.depth.data());
    flip_rows(r.rgb, out.rgb, static_cast<std::size_t>(w) * 3, h);
  }
  out.width = w;
  out.height = h;
  out.intrinsics = intrinsics(camera);
  out.extrinsics = extrinsics(camera);
  const double zn = m->vis.map.znear * m->stat.extent, zf = m->vis.map.zfar * m->stat.extent;
  linear_depth(r.depth, out.depth, w, h, !r.gl.invert, zn, zf, c.near, c.far);
  if (passes.noise) add_noise(camera, out);
  out.body.clear();
  if (!passes.segmentation) return;
  r.scene.flags[mjRND_SEGMENT] = 1;
  r.scene.flags[mjRND_IDCOLOR] = 1;
  mjr_render(viewport, &r.scene, &r.con);
  r.scene.flags[mjRND_SEGMENT] = 0;
  r.scene.flags[mjRND_IDCOLOR] = 0;
  r.rgb.resize(n * 3);
  mjr_readPixels(r.rgb.data(), nullptr, viewport, &r.con);
  flip_rows(r.rgb, r.seg, static_cast<std::size_t>(w) * 3, h);
  out.body.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const int id = r.seg[3 * i] + 256 * r.seg[3 * i + 1] + 65536 * r.seg[3 * i + 2];  // segid + 1
    if (id == 0 || id > r.scene.ngeom) continue;
    const mjvGeom& g = r.scene.geoms[id - 1];
    if (g.objtype == mjOBJ_GEOM && g.objid >= 0) out.body[i] = m->geom_bodyid[g.objid];
  }
}

}  // namespace rtamp::sim
