// EGL backends: the device platform (EGL_EXT_platform_device, any vendor's
// driver; a hardware device is preferred over Mesa's software one) and Mesa's
// surfaceless platform. Both make a context current without a surface; all
// rendering goes to FBOs and images. Each makes a desktop OpenGL 4.5 core
// context or, for Api::es310, an OpenGL ES 3.1 one (EGL_OPENGL_ES_API).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/context.h"

namespace pn {
namespace {

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return "EGL error " + std::to_string(code);
  }
}

bool lists_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

template <typename Fn>
Fn egl_proc(const char* name) {
  auto fn = reinterpret_cast<Fn>(eglGetProcAddress(name));
  if (fn == nullptr) throw Error(std::string(name) + " is not available");
  return fn;
}

class EglContext final : public Context {
 public:
  EglContext(Backend backend, Api api, EGLDisplay display) : Context(backend, api), display_(display) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor))
      throw Error("eglInitialize failed (" + egl_error_name(eglGetError()) + ")");
    initialized_ = true;
    const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
    const bool es = api == Api::es310;
    if (!lists_extension(extensions, "EGL_KHR_create_context") && (major < 1 || (major == 1 && minor < 5)))
      throw Error("EGL " + std::to_string(major) + "." + std::to_string(minor) +
                  " without EGL_KHR_create_context cannot ask for " + (es ? "a context version" : "a core profile"));
    if (es ? !eglBindAPI(EGL_OPENGL_ES_API) : !eglBindAPI(EGL_OPENGL_API))
      throw Error(es ? "eglBindAPI(EGL_OPENGL_ES_API) failed: no OpenGL ES"
                     : "eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL");

    // Mesa returns no config without EGL_PBUFFER_BIT; EGL_NO_CONFIG_KHR avoids the question (SPEC §8).
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!lists_extension(extensions, "EGL_KHR_no_config_context")) {
      const EGLint renderable = es ? EGL_OPENGL_ES3_BIT_KHR : EGL_OPENGL_BIT;
      const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, renderable, EGL_NONE};
      EGLint count = 0;
      if (!eglChooseConfig(display_, wanted, &config, 1, &count) || count == 0)
        throw Error(es ? "no EGL config for an OpenGL ES 3 pbuffer" : "no EGL config for a desktop OpenGL pbuffer");
    }
    for (EGLint debug : {EGL_TRUE, EGL_FALSE}) {
      const EGLint desktop[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_CONTEXT_OPENGL_DEBUG, debug, EGL_NONE};
      const EGLint embedded[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 1,
                                 EGL_CONTEXT_OPENGL_DEBUG, debug, EGL_NONE};
      context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, es ? embedded : desktop);
      if (context_ != EGL_NO_CONTEXT) break;
    }
    if (context_ == EGL_NO_CONTEXT)
      throw Error(std::string("eglCreateContext for ") + api_title(api) + " failed (" + egl_error_name(eglGetError()) +
                  ")");

    EGLSurface surface = EGL_NO_SURFACE;
    if (!lists_extension(extensions, "EGL_KHR_surfaceless_context")) {
      const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface_ = eglCreatePbufferSurface(display_, config, size);
      if (surface_ == EGL_NO_SURFACE)
        throw Error("no surfaceless contexts and no pbuffer (" + egl_error_name(eglGetError()) + ")");
      surface = surface_;
    }
    if (!eglMakeCurrent(display_, surface, surface, context_))
      throw Error("eglMakeCurrent failed (" + egl_error_name(eglGetError()) + ")");
    load(reinterpret_cast<GLADloadfunc>(eglGetProcAddress));
  }

  ~EglContext() override {
    if (!initialized_) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

 private:
  EGLDisplay display_;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
  bool initialized_ = false;
};

// Constructors that throw do not run the destructor: wrap so a half-made
// context is still torn down.
std::unique_ptr<Context> make_current(Backend backend, Api api, EGLDisplay display) {
  if (display == EGL_NO_DISPLAY) throw Error("no EGL display (" + egl_error_name(eglGetError()) + ")");
  EGLint major = 0, minor = 0;
  try {
    return std::make_unique<EglContext>(backend, api, display);
  } catch (...) {
    if (eglInitialize(display, &major, &minor)) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglTerminate(display);
    }
    throw;
  }
}

std::unique_ptr<Context> create_device_context(Api api) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  for (const char* ext : {"EGL_EXT_device_enumeration", "EGL_EXT_platform_device"})
    if (!lists_extension(client, ext)) throw Error(std::string("EGL client extension ") + ext + " missing");
  auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  auto platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");

  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count == 0) throw Error("eglQueryDevicesEXT found no device");
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  query_devices(count, devices.data(), &count);
  devices.resize(static_cast<size_t>(count));

  // Hardware devices first; Mesa lists llvmpipe as EGL_MESA_device_software.
  std::vector<EGLDeviceEXT> ordered;
  for (bool software : {false, true})
    for (EGLDeviceEXT d : devices)
      if (lists_extension(query_string(d, EGL_EXTENSIONS), "EGL_MESA_device_software") == software)
        ordered.push_back(d);

  std::string reasons;
  for (size_t i = 0; i < ordered.size(); ++i) {
    try {
      return make_current(Backend::egl_device, api, platform_display(EGL_PLATFORM_DEVICE_EXT, ordered[i], nullptr));
    } catch (const Error& e) {
      reasons += std::string(reasons.empty() ? "" : "; ") + "device " + std::to_string(i) + ": " + e.what();
    }
  }
  throw Error(reasons);
}

std::unique_ptr<Context> create_surfaceless_context(Api api) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!lists_extension(client, "EGL_MESA_platform_surfaceless"))
    throw Error("EGL client extension EGL_MESA_platform_surfaceless missing");
  auto platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  return make_current(Backend::egl_surfaceless, api,
                      platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
}

}  // namespace

std::unique_ptr<Context> create_egl_context(Backend backend, Api api) {
  return backend == Backend::egl_device ? create_device_context(api) : create_surfaceless_context(api);
}

}  // namespace pn
