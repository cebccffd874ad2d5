#include "gl/context.h"

#include <cstdio>
#include <type_traits>

#include "core/error.h"

namespace pn {

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::egl_device: return "egl-device";
    case Backend::egl_surfaceless: return "egl-surfaceless";
    case Backend::osmesa: return "osmesa";
  }
  return "?";
}

std::vector<Backend> compiled_backends() {
  std::vector<Backend> backends{Backend::egl_device, Backend::egl_surfaceless};
#ifdef PENUMBRA_HAVE_OSMESA
  backends.push_back(Backend::osmesa);
#endif
  return backends;
}

const char* api_name(Api api) { return api == Api::es310 ? "es310" : "gl450"; }
const char* api_title(Api api) { return api == Api::es310 ? "OpenGL ES 3.1" : "OpenGL 4.5 core"; }

Api parse_api(const std::string& name) {
  for (Api a : {Api::gl450, Api::es310})
    if (name == api_name(a)) return a;
  throw Error("API '" + name + "': expected one of gl450, es310");
}

Backend parse_backend(const std::string& name) {
  for (Backend b : {Backend::egl_device, Backend::egl_surfaceless, Backend::osmesa})
    if (name == backend_name(b)) return b;
  throw Error("backend '" + name + "': expected one of egl-device, egl-surfaceless, osmesa");
}

std::string Context::vendor() const { return reinterpret_cast<const char*>(gl_.GetString(GL_VENDOR)); }
std::string Context::renderer() const { return reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER)); }
std::string Context::version() const { return reinterpret_cast<const char*>(gl_.GetString(GL_VERSION)); }

bool Context::has_extension(const std::string& name) const {
  GLint count = 0;
  gl_.GetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
    if (const auto* e = reinterpret_cast<const char*>(gl_.GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i))); e && name == e)
      return true;
  return false;
}

void Context::load(GLADloadfunc get_proc) {
  const int version = gladLoadGLContext(&gl_, get_proc);
  if (version == 0) throw Error("could not load OpenGL functions");
  const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
  const std::string version_string = this->version();
  const bool es = version_string.rfind("OpenGL ES", 0) == 0;
  if (api_ == Api::gl450) {
    if (es) throw Error("context is '" + version_string + "', expected desktop OpenGL 4.5 core");
    if (major < 4 || (major == 4 && minor < 5))
      throw Error("context is OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                  ", expected 4.5 core (compute shaders, direct state access)");
    timer_queries_ = texture_views_ = debug_output_ = true;
  } else {
    if (!es) throw Error("context is '" + version_string + "', expected OpenGL ES 3.1");
    load_es(get_proc, major, minor);
  }
  if (debug_output_) {
    gl_.Enable(GL_DEBUG_OUTPUT);
    gl_.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    gl_.DebugMessageCallback(&Context::on_debug_message, this);
    gl_.DebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  }
}

// glad is generated for desktop GL 4.5 (cmake/glad.cmake). On an ES context it reads
// "OpenGL ES 3.2 Mesa ..." as version 3.2 and loads only the entry points of desktop GL
// 1.0-3.2, which ES 3.x shares by name and signature. The ES 3.0/3.1 functions below are in
// desktop GL only from 3.3-4.3 on, so glad leaves them null: they are loaded here by name into
// the same table fields (same prototypes), and the runner calls them as on desktop GL.
#define PN_ES31_FUNCTIONS(X)                                                                   \
  X(TexStorage2D) X(TexStorage3D)                             /* ES 3.0; desktop 4.2 */          \
  X(DispatchCompute) X(DispatchComputeIndirect)               /* ES 3.1; desktop 4.3 */          \
  X(BindImageTexture) X(MemoryBarrier) X(MemoryBarrierByRegion) /* ES 3.1; desktop 4.2/4.5 */    \
  X(GetBooleani_v) X(GetProgramInterfaceiv) X(GetProgramResourceIndex) X(GetProgramResourceName) \
  X(GetProgramResourceiv) X(GetProgramResourceLocation)       /* ES 3.1; desktop 4.3 */          \
  X(BindVertexBuffer) X(VertexAttribFormat) X(VertexAttribIFormat) X(VertexAttribBinding)        \
  X(VertexBindingDivisor)                                     /* ES 3.1; desktop 4.3 */

void Context::load_es(GLADloadfunc get_proc, int major, int minor) {
  if (major < 3 || (major == 3 && minor < 1))
    throw Error("context is OpenGL ES " + std::to_string(major) + "." + std::to_string(minor) +
                ", expected 3.1 (compute shaders, images)");
  std::string missing;
  const auto load_fn = [&](auto& field, const char* name) {
    field = reinterpret_cast<std::remove_reference_t<decltype(field)>>(get_proc(name));
    if (field == nullptr) missing += std::string(missing.empty() ? "" : ", ") + name;
  };
#define PN_LOAD_ES31(name) load_fn(gl_.name, "gl" #name);
  PN_ES31_FUNCTIONS(PN_LOAD_ES31)
#undef PN_LOAD_ES31
  if (!missing.empty()) throw Error("OpenGL ES 3.1 functions missing: " + missing);
  GLint invocations = 0;
  gl_.GetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  if (invocations < 128) throw Error("no compute shaders (GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS " +
                                     std::to_string(invocations) + ", expected >= 128)");
  // Every target the passes draw into or the runner reads back is R32F, RG32F or RGBA32F.
  if (!has_extension("GL_EXT_color_buffer_float"))
    throw Error("GL_EXT_color_buffer_float missing: float textures are not colour-renderable");
  // Views of a layer (the pyramid's level 0): glTextureViewOES / EXT, same prototype as GL 4.3's.
  for (const char* suffix : {"OES", "EXT"})
    if (!texture_views_ && has_extension(std::string("GL_") + suffix + "_texture_view")) {
      load_fn(gl_.TextureView, (std::string("glTextureView") + suffix).c_str());
      texture_views_ = gl_.TextureView != nullptr;
    }
  if (!texture_views_) gl_.TextureView = nullptr;
  // GL_TIMESTAMP queries: GL_EXT_disjoint_timer_query (GL_TIMESTAMP_EXT has GL_TIMESTAMP's value).
  if (has_extension("GL_EXT_disjoint_timer_query")) {
    load_fn(gl_.QueryCounter, "glQueryCounterEXT");
    load_fn(gl_.GetQueryObjectui64v, "glGetQueryObjectui64vEXT");
    timer_queries_ = gl_.QueryCounter != nullptr && gl_.GetQueryObjectui64v != nullptr;
  }
  // Debug output: core in ES 3.2; in ES 3.1 GL_KHR_debug, whose ES entry points carry "KHR".
  const bool core_debug = major > 3 || minor >= 2;
  if (core_debug || has_extension("GL_KHR_debug")) {
    const std::string suffix = core_debug ? "" : "KHR";
    load_fn(gl_.DebugMessageCallback, ("glDebugMessageCallback" + suffix).c_str());
    load_fn(gl_.DebugMessageControl, ("glDebugMessageControl" + suffix).c_str());
    debug_output_ = gl_.DebugMessageCallback != nullptr && gl_.DebugMessageControl != nullptr;
  }
}

void GLAD_API_PTR Context::on_debug_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei length,
                                            const GLchar* message, const void* self) {
  // Errors and high-severity messages fail the operation; performance notes
  // and other chatter do not.
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  auto* context = static_cast<const Context*>(self);
  context->debug_errors_.emplace_back(message, length > 0 ? static_cast<size_t>(length) : std::char_traits<char>::length(message));
}

void Context::throw_if_gl_error(const std::string& what) const {
  std::string problems;
  for (GLenum code = gl_.GetError(); code != GL_NO_ERROR; code = gl_.GetError()) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", code);
    problems += std::string(problems.empty() ? "" : "; ") + "glGetError " + hex;
  }
  for (const std::string& m : debug_errors_) problems += std::string(problems.empty() ? "" : "; ") + m;
  debug_errors_.clear();
  if (!problems.empty()) throw Error(what + ": OpenGL error: " + problems, ExitCode::failed);
}

void Context::discard_gl_errors() const {
  while (gl_.GetError() != GL_NO_ERROR) {
  }
  debug_errors_.clear();
}

std::unique_ptr<Context> create_context(std::optional<Backend> forced, Api api) {
  const std::vector<Backend> order = forced ? std::vector<Backend>{*forced} : compiled_backends();
  std::string reasons;
  for (Backend backend : order) {
    try {
      if (backend == Backend::osmesa) return create_osmesa_context(api);
      return create_egl_context(backend, api);
    } catch (const Error& e) {
      reasons += std::string(reasons.empty() ? "" : "; ") + backend_name(backend) + ": " + e.what();
    }
  }
  throw Error(std::string("no headless ") + (api == Api::es310 ? "OpenGL ES 3.1" : "OpenGL 4.5") +
                  " context: tried " + reasons,
              ExitCode::no_context);
}

}  // namespace pn
