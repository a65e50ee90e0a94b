#include "rtamp/sim/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

#include "rtamp/util/error.hpp"

namespace rtamp::sim {

namespace {

EGLDisplay surfaceless_display() {
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display) {
    EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) return d;
  }
  return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

}  // namespace

EglContext::EglContext(int width, int height) {
  auto fail = [&](const std::string& what) {
    release();
    throw Error("offscreen rendering unavailable: " + what);
  };
  EGLDisplay display = surfaceless_display();
  display_ = display;
  if (display == EGL_NO_DISPLAY) fail("no EGL display (need Mesa's EGL: libegl-mesa0)");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    display_ = nullptr;
    fail("eglInitialize failed");
  }
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                   EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24,
                                   EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint nconfig = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &nconfig) || nconfig < 1) fail("no EGL config");
  const EGLint pbuffer_attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  surface_ = eglCreatePbufferSurface(display, config, pbuffer_attribs);
  if (surface_ == EGL_NO_SURFACE) fail("no pbuffer surface");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(OpenGL) failed");
  context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
  if (context_ == EGL_NO_CONTEXT) fail("no OpenGL context");
  // Current once here, to prove it can be (then on no thread until a Use).
  Use check(*this);
  if (!check.ok()) fail("eglMakeCurrent failed");
}

EglContext::~EglContext() { release(); }

EglContext::Use::Use(const EglContext& c) noexcept
    : display_(c.display_),
      previous_display_(eglGetCurrentDisplay()),
      previous_context_(eglGetCurrentContext()),
      previous_draw_(eglGetCurrentSurface(EGL_DRAW)),
      previous_read_(eglGetCurrentSurface(EGL_READ)) {
  ok_ = c.display_ != nullptr && eglMakeCurrent(c.display_, c.surface_, c.surface_, c.context_);
}

EglContext::Use::~Use() {
  if (!ok_) return;
  if (previous_context_ != EGL_NO_CONTEXT && previous_display_ != EGL_NO_DISPLAY)
    eglMakeCurrent(previous_display_, previous_draw_, previous_read_, previous_context_);
  else
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

void EglContext::release() {
  if (display_ == nullptr) return;
  // Current on no thread: every Use has ended.
  if (context_ != nullptr) eglDestroyContext(display_, context_);
  if (surface_ != nullptr) eglDestroySurface(display_, surface_);
  display_ = context_ = surface_ = nullptr;
}

}  // namespace rtamp::sim
