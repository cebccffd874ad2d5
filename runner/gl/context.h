// A headless OpenGL 4.5 core context (SPEC §6) behind one interface, with one
// implementation per way of getting it: EGL device platform, EGL surfaceless
// (Mesa), OSMesa. The context owns its GL function table (glad, mx mode) and
// turns GL debug output into errors.
#pragma once

#include <glad/gl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pn {

enum class Backend { egl_device, egl_surfaceless, osmesa };

const char* backend_name(Backend backend);
Backend parse_backend(const std::string& name);  // throws Error naming the accepted values
std::vector<Backend> compiled_backends();       // in the order they are tried

class Context {
 public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const GladGLContext& gl() const { return gl_; }
  Backend backend() const { return backend_; }
  std::string vendor() const;
  std::string renderer() const;
  std::string version() const;

  // Throws Error(ExitCode::failed) naming `what` when glGetError or the debug
  // output reported an error since the last call; clears both.
  void throw_if_gl_error(const std::string& what) const;

  // Forgets pending errors that the caller reports itself (a shader compile
  // log, which the debug output would otherwise repeat).
  void discard_gl_errors() const;

 protected:
  explicit Context(Backend backend) : backend_(backend) {}
  // Loads the function table through `get_proc`, checks the version and
  // compute support, and installs the debug callback. Throws Error on failure.
  void load(GLADloadfunc get_proc);

 private:
  static void GLAD_API_PTR on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                            GLsizei length, const GLchar* message, const void* self);
  Backend backend_;
  GladGLContext gl_{};
  mutable std::vector<std::string> debug_errors_;
};

// Makes a context with the given backend, or the first that works in
// compiled_backends() order. Throws Error(ExitCode::no_context) whose message
// lists every backend tried and why it failed.
std::unique_ptr<Context> create_context(std::optional<Backend> forced = std::nullopt);

// Backend implementations; each throws Error with the reason it failed.
std::unique_ptr<Context> create_egl_context(Backend backend);
std::unique_ptr<Context> create_osmesa_context();

}  // namespace pn
