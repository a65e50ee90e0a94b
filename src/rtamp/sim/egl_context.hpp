// A headless OpenGL context (docs/design.md "Headless by default"): EGL on Mesa's
// surfaceless platform (no display, no X server) with a pbuffer, for MuJoCo's
// offscreen renderer. The overview Renderer and the CameraRig each own one.
// Invariants: the context is current on no thread except inside an EglContext::Use,
// which makes it current on the calling thread and, when it ends, restores what that
// thread had current before (usually nothing). So whichever thread renders may do so
// (EGL refuses to make a context current on a thread while another thread holds it:
// `rtamp serve` builds the episode on one thread and steps it on another). The EGL
// display is one per process and shared by every context: it stays initialised
// (terminating it would end the other contexts).
#pragma once

namespace rtamp::sim {

class EglContext {
 public:
  // Throws rtamp::Error "offscreen rendering unavailable: ..." when EGL fails.
  EglContext(int width, int height);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // The context current on this thread for the guard's life. ok() is false when EGL
  // refused (the caller reports it; destructors ignore it).
  class Use {
   public:
    explicit Use(const EglContext& context) noexcept;
    ~Use();
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;
    bool ok() const { return ok_; }

   private:
    void* display_;  // the context's (process-wide: it outlives the context)
    bool ok_ = false;
    void* previous_display_ = nullptr;
    void* previous_context_ = nullptr;
    void* previous_draw_ = nullptr;
    void* previous_read_ = nullptr;
  };

 private:
  void release();
  void* display_ = nullptr;
  void* context_ = nullptr;
  void* surface_ = nullptr;
};

}  // namespace rtamp::sim
