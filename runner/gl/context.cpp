#include "gl/context.h"

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

Backend parse_backend(const std::string& name) {
  for (Backend b : {Backend::egl_device, Backend::egl_surfaceless, Backend::osmesa})
    if (name == backend_name(b)) return b;
  throw Error("backend '" + name + "': expected one of egl-device, egl-surfaceless, osmesa");
}

std::string Context::vendor() const { return reinterpret_cast<const char*>(gl_.GetString(GL_VENDOR)); }
std::string Context::renderer() const { return reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER)); }
std::string Context::version() const { return reinterpret_cast<const char*>(gl_.GetString(GL_VERSION)); }

void Context::load(GLADloadfunc get_proc) {
  const int version = gladLoadGLContext(&gl_, get_proc);
  if (version == 0) throw Error("could not load OpenGL functions");
  const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
  if (major < 4 || (major == 4 && minor < 5))
    throw Error("context is OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                ", expected 4.5 core (compute shaders, direct state access)");
  gl_.Enable(GL_DEBUG_OUTPUT);
  gl_.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  gl_.DebugMessageCallback(&Context::on_debug_message, this);
  gl_.DebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
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

std::unique_ptr<Context> create_context(std::optional<Backend> forced) {
  const std::vector<Backend> order = forced ? std::vector<Backend>{*forced} : compiled_backends();
  std::string reasons;
  for (Backend backend : order) {
    try {
      if (backend == Backend::osmesa) return create_osmesa_context();
      return create_egl_context(backend);
    } catch (const Error& e) {
      reasons += std::string(reasons.empty() ? "" : "; ") + backend_name(backend) + ": " + e.what();
    }
  }
  throw Error("no headless OpenGL 4.5 context: tried " + reasons, ExitCode::no_context);
}

}  // namespace pn
