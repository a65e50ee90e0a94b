// A headless OpenGL context (docs/design.md "Headless by default"): EGL on Mesa's
// surfaceless platform (no display, no X server) with a pbuffer, for MuJoCo's
// offscreen renderer. The overview Renderer and the CameraRig each own one.
// Invariants: made current on creation; make_current() before rendering when a
// thread holds several. The EGL display is one per process and shared by every
// context: it stays initialised (terminating it would end the other contexts).
#pragma once

namespace rtamp::sim {

class EglContext {
 public:
  // Throws rtamp::Error "offscreen rendering unavailable: ..." when EGL fails.
  EglContext(int width, int height);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;
  // False when EGL refuses (the caller reports it; destructors ignore it).
  bool make_current() const noexcept;

 private:
  void release();
  void* display_ = nullptr;
  void* context_ = nullptr;
  void* surface_ = nullptr;
};

}  // namespace rtamp::sim
