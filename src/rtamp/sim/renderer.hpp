// Offscreen pictures of the simulation (docs/design.md "Headless by default; pictures and
// videos through offscreen rendering"): a headless EGL context (egl_context.hpp),
// MuJoCo's renderer into its offscreen buffer, PNG through libpng, MP4
// through a pipe to Debian's ffmpeg. Nothing here runs unless a Renderer is created, so
// runs without pictures pay nothing.
//
// Invariants: one Renderer owns one EGL context, current on the creating thread; frames
// are RGB, rows top-down; the camera is the model's fixed "overview" camera; region
// outlines are model geoms (always drawn); shadows, reflections and skybox are off.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "rtamp/sim/simulation.hpp"

namespace rtamp::sim {

struct RenderOptions {
  int width = 640;
  int height = 480;
  bool labels = false;  // draw body names
};

class Renderer {
 public:
  // Throws rtamp::Error when no EGL display / context can be made.
  Renderer(const Simulation& sim, RenderOptions options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int width() const { return options_.width; }
  int height() const { return options_.height; }
  // Renders the current state; `rgb` gets width*height*3 bytes, top row first.
  void render(std::vector<std::uint8_t>& rgb);
  // Pixel (column x, row y from the top) where a world point projects; false if behind.
  bool project(const Eigen::Vector3d& p, double& x, double& y) const;

 private:
  struct Impl;
  Impl* impl_;
  const Simulation& sim_;
  RenderOptions options_;
  std::vector<std::uint8_t> flip_;
};

// An RGB image (width*height*3 bytes, top row first) as PNG bytes, in memory (the MCAP
// file's and the page's camera images). Throws rtamp::Error on a size mismatch.
std::string encode_png(const std::vector<std::uint8_t>& rgb, int width, int height);
// Writes an RGB image as PNG. Throws rtamp::Error when the file cannot be written.
void write_png(const std::string& path, const std::vector<std::uint8_t>& rgb, int width, int height);
// Writes a 16-bit grey image (a depth map in mm) as PNG.
void write_png16(const std::string& path, const std::vector<std::uint16_t>& gray, int width, int height);

// Frames piped to `ffmpeg ... -c:v libx264 -pix_fmt yuv420p path`.
class VideoWriter {
 public:
  VideoWriter(const std::string& path, int width, int height, int fps);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;
  void add(const std::vector<std::uint8_t>& rgb);
  // Closes the pipe; throws rtamp::Error if ffmpeg failed.
  void close();
  int frames() const { return frames_; }

 private:
  std::FILE* pipe_ = nullptr;
  std::string path_;
  int width_, height_, frames_ = 0;
};

}  // namespace rtamp::sim
