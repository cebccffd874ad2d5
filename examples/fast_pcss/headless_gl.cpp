// Headless EGL in three steps: a display that needs no window system (the
// EGL device platform, which any vendor's driver may offer, or Mesa's
// surfaceless platform), a desktop GL 4.5 core context on it, and that
// context made current without a surface where EGL allows (else on a 1x1
// pbuffer). Then glad loads the GL functions through eglGetProcAddress.
#include "headless_gl.h"

#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace example {
namespace {

bool has_extension(const char* list, const char* name) {
  const size_t n = std::strlen(name);
  for (const char* p = list ? std::strstr(list, name) : nullptr; p; p = std::strstr(p + n, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::string egl_error() {
  char text[32];
  std::snprintf(text, sizeof text, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return text;
}

// The first display that initializes: the first EGL device, then Mesa's surfaceless platform.
EGLDisplay open_display(std::string& tried) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!get_platform_display) {
    tried = "no eglGetPlatformDisplayEXT";
    return EGL_NO_DISPLAY;
  }
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLDeviceEXT device = nullptr;
  EGLint count = 0;
  if (has_extension(client, "EGL_EXT_platform_device") && query_devices && query_devices(1, &device, &count) &&
      count > 0) {
    display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    tried += "EGL device platform (" + egl_error() + "); ";
  } else {
    tried += "EGL device platform (no device); ";
  }
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    tried += "Mesa surfaceless platform (" + egl_error() + ")";
  } else {
    tried += "Mesa surfaceless platform (not offered)";
  }
  return EGL_NO_DISPLAY;
}

}  // namespace

HeadlessGl::HeadlessGl() {
  std::string tried;
  display_ = open_display(tried);
  if (display_ == EGL_NO_DISPLAY) throw std::runtime_error("no headless EGL display: tried " + tried);
  const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
  const auto fail = [&](const std::string& what) {
    std::runtime_error error(what + " (" + egl_error() + ")");
    release();  // a constructor that throws runs no destructor
    return error;
  };
  if (!eglBindAPI(EGL_OPENGL_API)) throw fail("eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL");

  // Mesa offers EGL_KHR_no_config_context; elsewhere ask for a pbuffer-capable GL config.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display_, wanted, &config, 1, &count) || count == 0)
      throw fail("no EGL config for a desktop OpenGL pbuffer");
  }
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
  if (context_ == EGL_NO_CONTEXT) throw fail("eglCreateContext for OpenGL 4.5 core failed");

  if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
    const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface_ = eglCreatePbufferSurface(display_, config, size);
    if (surface_ == EGL_NO_SURFACE) throw fail("no surfaceless context and no pbuffer");
  }
  if (!eglMakeCurrent(display_, surface_, surface_, context_)) throw fail("eglMakeCurrent failed");
  if (gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) < GLAD_MAKE_VERSION(4, 5))
    throw fail("the context is not OpenGL 4.5");
}

HeadlessGl::~HeadlessGl() { release(); }

void HeadlessGl::release() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  eglTerminate(display_);
  display_ = EGL_NO_DISPLAY;
}

std::string HeadlessGl::renderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }

}  // namespace example
