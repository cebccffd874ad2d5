// A headless OpenGL 4.5 core context through EGL: no window, no display
// server. Everything the example draws goes into framebuffer objects.
#pragma once

#include <EGL/egl.h>

#include <string>

namespace example {

class HeadlessGl {
 public:
  // Makes a desktop OpenGL 4.5 core context current and loads the GL
  // functions (glad). Throws std::runtime_error saying what was tried and why
  // it failed when the machine has none.
  HeadlessGl();
  ~HeadlessGl();
  HeadlessGl(const HeadlessGl&) = delete;
  HeadlessGl& operator=(const HeadlessGl&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  void release();

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
};

}  // namespace example
