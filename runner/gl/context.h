// A headless OpenGL 4.5 core context (SPEC §6) — or, asked for, an OpenGL ES 3.1
// one — behind one interface, with one implementation per way of getting it: EGL
// device platform, EGL surfaceless (Mesa), OSMesa (desktop GL only). The context
// owns its GL function table (glad, mx mode) and turns GL debug output into errors.
#pragma once

#include <glad/gl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device/loop_census_record.h"
#include "device/query_device.h"
#include "shader/loop_guard.h"

namespace pn {

enum class Backend { egl_device, egl_surfaceless, osmesa };

const char* backend_name(Backend backend);
Backend parse_backend(const std::string& name);  // throws Error naming the accepted values
std::vector<Backend> compiled_backends();       // in the order they are tried

// The API a context speaks. The runner uses only what both have (bind-to-edit objects, compute,
// images, SSBOs) plus one named fallback per desktop-only feature (gl/texture.h, gl/gpu_timer.h);
// passes are compiled for the API's GLSL target (gl450 or es310, shader/target.h).
enum class Api { gl450, es310 };

const char* api_name(Api api);   // "gl450", "es310"
const char* api_title(Api api);  // "OpenGL 4.5 core", "OpenGL ES 3.1"
Api parse_api(const std::string& name);  // throws Error naming the accepted values

// A context is also an executor of the query passes (device/query_device.h; gl/query_device_gl.cpp).
class Context : public QueryDevice {
 public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const GladGLContext& gl() const { return gl_; }
  Backend backend() const { return backend_; }
  Api api() const { return api_; }
  bool is_es() const { return api_ == Api::es310; }
  // Features beyond the shared subset, found by load(): GL 4.5 core has them all; an ES context
  // has them with an extension (GL_EXT_disjoint_timer_query, GL_OES/EXT_texture_view, ES 3.2 or
  // GL_KHR_debug).
  bool has_timer_queries() const { return timer_queries_; }
  bool has_texture_views() const { return texture_views_; }
  bool has_debug_output() const { return debug_output_; }
  bool has_extension(const std::string& name) const;
  std::string vendor() const;
  std::string renderer() const;
  std::string version() const;

  // Throws Error(ExitCode::failed) naming `what` when glGetError or the debug
  // output reported an error since the last call; clears both.
  void throw_if_gl_error(const std::string& what) const;

  // Programs compiled and dispatches issued after this call follow `bounds`.
  void set_dispatch_bounds(const DispatchBounds& bounds) { bounds_ = bounds; }
  const DispatchBounds& dispatch_bounds() const { return bounds_; }

  // While `census` is set (null: none), compute passes compiled count their loops
  // (shader/loop_census.h) and each of their dispatches adds a record to it. A program keeps
  // what it was compiled with: a census needs programs of its own (the bench's estimate run).
  void set_loop_census(LoopCensus* census) const { census_ = census; }
  LoopCensus* loop_census() const { return census_; }

  // Forgets pending errors that the caller reports itself (a shader compile
  // log, which the debug output would otherwise repeat).
  void discard_gl_errors() const;

  // QueryDevice, in gl/query_device_gl.cpp.
  std::string query_api() const override;
  std::unique_ptr<QueryProgram> compile_query(const SourceTree& tree, const std::string& pass,
                                              const std::vector<Define>& defines) const override;
  std::unique_ptr<DeviceTexture> upload(const Image& image) const override;
  std::unique_ptr<QueryBatch> make_batch(const std::vector<Image>& inputs, std::size_t results,
                                         std::size_t word_results) const override;
  void dispatch(const QueryProgram& program, const QueryBindings& bindings, const QueryBatch& batch,
                const std::vector<QueryTexture>& textures, const QueryBlock& block) const override;
  std::unique_ptr<DeviceTexture> make_texture(const TextureShape& shape) const override;
  Image read_texture(const DeviceTexture& texture, int level, int layer) const override;
  std::vector<std::uint32_t> read_words(const DeviceTexture& texture, int level, int layer) const override;
  std::unique_ptr<DeviceTexture> layer_texture(const DeviceTexture& array, int layer) const override;
  std::unique_ptr<DeviceBuffer> make_buffer(std::size_t bytes) const override;
  void write_buffer(const DeviceBuffer& buffer, std::size_t offset, std::size_t bytes, const void* data) const override;
  void run(const QueryProgram& program, const PassResources& resources, int width, int height) const override;
  void run_indirect(const QueryProgram& program, const PassResources& resources,
                    const DeviceBuffer& groups) const override;
  void clear_texture(const DeviceTexture& texture, const float value[4]) const override;
  std::unique_ptr<StageTimes> stage_clock() const override;
  std::unique_ptr<QueryProgram> compile_raster(const SourceTree& tree, const std::string& vertex,
                                               const std::string& fragment, TexelFormat target) const override;
  std::unique_ptr<QueryProgram> compile_full_screen(const SourceTree& tree, const std::string& fragment,
                                                    TexelFormat target,
                                                    const std::vector<Define>& defines) const override;
  std::unique_ptr<DeviceTexture> draw_full_screen(const QueryProgram& program, int size,
                                                  const PassResources& resources) const override;
  std::unique_ptr<DeviceVertices> make_vertices(const std::vector<glm::vec3>& vertices) const override;
  void write_vertices(const DeviceVertices& to, const std::vector<glm::vec3>& vertices, std::size_t first,
                      std::size_t count) const override;
  std::unique_ptr<DeviceRasterTarget> make_raster_target(int size, TexelFormat format) const override;
  void clear_target(const DeviceRasterTarget& target, const float colour[4],
                    const std::vector<TexelRect>& rects) const override;
  void copy_target(const DeviceRasterTarget& source, const DeviceRasterTarget& target,
                   const std::vector<TexelRect>& rects) const override;
  void draw(const QueryProgram& program, const DeviceVertices& vertices, const std::vector<VertexRun>& runs,
            const DeviceRasterTarget& target, const std::vector<TexelRect>& rects,
            const PassResources& resources) const override;
  std::unique_ptr<DeviceTexture> draw_triangles(const QueryProgram& program, const std::vector<glm::vec3>& vertices,
                                                int size, const float clear[4],
                                                const PassResources& resources) const override;
  int storage_channels(int channels) const override;

 protected:
  explicit Context(Backend backend, Api api = Api::gl450) : backend_(backend), api_(api) {}
  // Loads the function table through `get_proc`, checks the version (4.5 core, or ES 3.1 with
  // float render targets) and compute support, and installs the debug callback where there is
  // debug output (else glGetError alone reports errors). Throws Error on failure.
  void load(GLADloadfunc get_proc);

 private:
  static void GLAD_API_PTR on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                            GLsizei length, const GLchar* message, const void* self);
  void load_es(GLADloadfunc get_proc, int major, int minor);
  Backend backend_;
  Api api_;
  bool timer_queries_ = false, texture_views_ = false, debug_output_ = false;
  GladGLContext gl_{};
  mutable std::vector<std::string> debug_errors_;
  DispatchBounds bounds_;
  mutable LoopCensus* census_ = nullptr;  // borrowed while set: the caller's
};

// Makes a context of `api` with the given backend, or the first that works in
// compiled_backends() order. Throws Error(ExitCode::no_context) whose message
// names the API and lists every backend tried and why it failed.
std::unique_ptr<Context> create_context(std::optional<Backend> forced = std::nullopt, Api api = Api::gl450);

// Backend implementations; each throws Error with the reason it failed.
std::unique_ptr<Context> create_egl_context(Backend backend, Api api = Api::gl450);
std::unique_ptr<Context> create_osmesa_context(Api api = Api::gl450);

}  // namespace pn
