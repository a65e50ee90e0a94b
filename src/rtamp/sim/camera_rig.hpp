// The scenario's cameras rendered headless from the running simulation
// (docs/perception.md): for a named camera, its RGB image, its metric depth (the
// z-buffer linearised, outside the camera's range 0, then its noise model applied),
// and MuJoCo's segmentation pass mapped to body ids, with intrinsics and extrinsics in
// OpenCV's convention (pinhole.hpp). The segmentation pass is the truth of which body
// a pixel shows: tests score perception against it; perception itself must not use it.
//
// Invariants: one rig owns one EGL context (egl_context.hpp) and MuJoCo render context,
// sized for the largest camera, without multisampling (a pixel's colour, depth and
// segment belong to one surface point), its round shapes as 12-gons and its flat faces as
// single quads (cheaper for a CPU renderer; the model's own settings are left as they
// were); images are top row first; a wrist camera's extrinsics
// follow the arm (computed from the simulation's current state); the depth noise is
// drawn from the rig's own generator, so a seed gives the same images; the read-back and
// intermediate images are kept, so a frame after the first allocates nothing (given an
// `out` of that camera's size).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "rtamp/sim/pinhole.hpp"
#include "rtamp/sim/simulation.hpp"
#include "rtamp/world/camera.hpp"

namespace rtamp::sim {

struct CameraImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes a pixel
  std::vector<float> depth;       // m along the optical axis; 0 = no reading
  std::vector<int> body;          // segmentation pass: MuJoCo body id; -1 = background (or no body)
  Intrinsics intrinsics;
  Extrinsics extrinsics;
};

struct CameraPasses {
  bool noise = true;         // apply the camera's depth noise
  bool segmentation = true;  // render the segmentation pass (a second render)
};

class CameraRig {
 public:
  // Throws rtamp::Error when offscreen rendering is unavailable or a camera is not
  // in the simulation's model (mjcf_builder.hpp names them).
  CameraRig(const Simulation& sim, std::vector<world::Camera> cameras, std::uint64_t seed = 1);
  ~CameraRig();
  CameraRig(const CameraRig&) = delete;
  CameraRig& operator=(const CameraRig&) = delete;

  const std::vector<world::Camera>& cameras() const { return cameras_; }
  // Index of the named camera; rtamp::Error "unknown camera 'x' (cameras: ...)" at `where`.
  std::size_t index(const std::string& name, const SourceLocation& where) const;
  Intrinsics intrinsics(std::size_t camera) const;
  Extrinsics extrinsics(std::size_t camera) const;  // at the simulation's current state
  void render(std::size_t camera, CameraImage& out, CameraPasses passes = {});
  // Whether the read-back takes the images top row first from the driver
  // (GL_MESA_pack_invert, when it has it) or reads them bottom row first and turns them
  // (the path for other drivers); the same images either way. On only if the driver has it.
  bool pack_invert() const;
  void set_pack_invert(bool on);
  // The camera's depth noise applied to `image`'s clean depth (a render without the
  // noise pass): render(noise) is render(no noise) then this. Touches only image.depth
  // and the rig's noise state, never OpenGL, so another thread may meanwhile read the
  // rest of the image.
  void add_noise(std::size_t camera, CameraImage& image);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  const Simulation& sim_;
  std::vector<world::Camera> cameras_;
  std::vector<int> mj_camera_;  // MuJoCo camera id of each
  std::mt19937_64 rng_;
};

}  // namespace rtamp::sim
