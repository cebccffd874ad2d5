#include "gl/compute_program.h"

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "core/format.h"
#include "shader/diagnostic.h"
#include "shader/flatten.h"
#include "shader/glslang_compiler.h"
#include "shader/loop_census.h"
#include "shader/loop_guard.h"

namespace pn {
namespace {

std::string first_lines(const std::vector<Diagnostic>& diagnostics, const std::string& raw) {
  if (diagnostics.empty()) return raw;
  std::string out;
  for (const Diagnostic& d : diagnostics) out += (out.empty() ? "" : "\n") + d.str();
  return out;
}

GLenum shader_type(Stage stage) {
  switch (stage) {
    case Stage::vertex: return GL_VERTEX_SHADER;
    case Stage::fragment: return GL_FRAGMENT_SHADER;
    case Stage::compute: return GL_COMPUTE_SHADER;
  }
  return GL_COMPUTE_SHADER;
}

}  // namespace

GlObject link_program(const Context& context, const std::string& name, const std::vector<const ShaderSource*>& stages) {
  const auto& gl = context.gl();
  const auto log_of = [&](GLuint id, bool is_program) {
    GLint length = 0;
    is_program ? gl.GetProgramiv(id, GL_INFO_LOG_LENGTH, &length) : gl.GetShaderiv(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    is_program ? gl.GetProgramInfoLog(id, length, nullptr, log.data())
               : gl.GetShaderInfoLog(id, length, nullptr, log.data());
    return std::string(log.c_str());
  };
  GlObject program(context, GlKind::program);
  std::vector<GlObject> shaders;
  for (const ShaderSource* source : stages) {
    GlObject shader(context, GlKind::shader, shader_type(source->stage));
    const std::string driver_text = source->driver_text();
    const char* text = driver_text.c_str();
    gl.ShaderSource(shader.id(), 1, &text, nullptr);
    gl.CompileShader(shader.id());
    GLint ok = 0;
    gl.GetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = log_of(shader.id(), false);
      const std::string entry = source->files.empty() ? name : source->files.front();
      const LocationMap by_physical_line = [&](int, int line) { return source->origin_of_line(line); };
      context.discard_gl_errors();  // the mapped log below says it better
      throw Error(name + ": the GL driver rejected the pass:\n" +
                      first_lines(parse_info_log(log, by_physical_line, entry), log),
                  ExitCode::failed);
    }
    gl.AttachShader(program.id(), shader.id());
    shaders.push_back(std::move(shader));
  }
  gl.LinkProgram(program.id());
  GLint ok = 0;
  gl.GetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    context.discard_gl_errors();
    throw Error(name + ": the GL driver could not link the pass: " + log_of(program.id(), true), ExitCode::failed);
  }
  context.throw_if_gl_error(name + ": building the program");
  return program;
}

namespace {

// glslang's process-wide state for the guard's preprocessor, kept while the runner runs (its
// built-in tables are made once, not once a pass).
const GlslangProcess& glslang_process() {
  static const GlslangProcess process;
  return process;
}

// The last storage buffer binding: passes number theirs from 0.
GLuint last_storage_binding(const Context& context) {
  GLint bindings = 0;
  context.gl().GetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
  return static_cast<GLuint>(std::max(bindings, 1) - 1);
}

// The source as compiled: under DispatchBounds, glslang's preprocessed text with every loop guarded.
ShaderSource bounded_source(const Context& context, const ShaderSource& source, std::vector<GuardedLoop>& loops,
                            GLuint& binding) {
  if (!context.dispatch_bounds().enabled || source.stage != Stage::compute) return source;
  binding = last_storage_binding(context);
  ShaderSource guarded = source;
  loops = guard_loops(glslang_process(), guarded, driver_target(context),
                      {binding, context.dispatch_bounds().loop_iterations});
  return guarded;
}

}  // namespace

ComputeProgram::ComputeProgram(const Context& context, const std::string& name, const ShaderSource& source,
                               const std::vector<Define>& defines)
    : context_(&context), name_(name), defines_(defines), census_(context.loop_census()) {
  ShaderSource compiled;
  if (census_ && source.stage == Stage::compute) {  // counted, not guarded: the bench's estimate run
    compiled = source;
    census_loops_ = census_loops(glslang_process(), compiled, driver_target(context), last_storage_binding(context));
  } else {
    census_ = nullptr;
    compiled = bounded_source(context, source, loops_, guard_binding_);
  }
  program_ = link_program(context, name, {&compiled});
  context.gl().GetProgramiv(program_.id(), GL_COMPUTE_WORK_GROUP_SIZE, local_size_);
  if (context.dispatch_bounds().enabled) {
    const LoopGuardState zero;
    guard_state_ = make_buffer(context, sizeof zero, &zero, GL_DYNAMIC_READ);
  }
}

void ComputeProgram::run(const std::string& what, const std::function<void()>& issue) const {
  const auto& gl = context_->gl();
  const DispatchBounds& bounds = context_->dispatch_bounds();
  if (!bounds.enabled || guard_state_.id() == 0) return issue();  // the caller checks for GL errors
  const LoopGuardState zero;
  write_buffer(*context_, guard_state_, 0, sizeof zero, &zero);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, guard_binding_, guard_state_.id());
  issue();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, guard_binding_, 0);
  context_->throw_if_gl_error(name_ + ": " + what);

  // A driver that queues the work returns at once: the deadline is the fence's. (llvmpipe runs
  // a dispatch inside the call; there the loop guard is what ends an endless loop.)
  GLsync fence = gl.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  const auto timeout_ns = static_cast<GLuint64>(bounds.timeout_s * 1e9);
  const GLenum waited = gl.ClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, timeout_ns);
  gl.DeleteSync(fence);
  if (waited == GL_TIMEOUT_EXPIRED)
    throw Error(name_ + ": " + what + " did not finish within " + format_number("%g", bounds.timeout_s) + " s",
                ExitCode::failed);
  if (waited == GL_WAIT_FAILED) throw Error(name_ + ": " + what + ": waiting for it failed", ExitCode::failed);

  LoopGuardState state;
  read_buffer(*context_, guard_state_, 0, sizeof state, &state);
  throw_if_loop_tripped(state, loops_, bounds.loop_iterations, name_ + ": " + what);
}

void ComputeProgram::run_counted(const std::string& what, const int groups[2], const std::function<void()>& issue) const {
  const auto& gl = context_->gl();
  LoopCensusRecord r;
  r.pass = name_, r.defines = defines_, r.loops = census_loops_;
  for (int k = 0; k < 3; ++k) r.local_size[k] = local_size_[k];
  r.groups[0] = groups[0], r.groups[1] = groups[1];
  const std::size_t words = static_cast<std::size_t>(r.invocations()) *
                            (census_loops_.size() + 1);
  std::vector<std::uint32_t> words_read(std::max<std::size_t>(words, 1), 0u);
  const GlObject counts = make_buffer(*context_, words_read.size() * sizeof(std::uint32_t), words_read.data(), GL_DYNAMIC_READ);
  const GLuint binding = last_storage_binding(*context_);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, counts.id());
  issue();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  context_->throw_if_gl_error(name_ + ": " + what + " (loop census)");
  read_buffer(*context_, counts, 0, words_read.size() * sizeof(std::uint32_t), words_read.data());
  reduce_census_counts(r, words_read);
  census_->records.push_back(std::move(r));
}

void ComputeProgram::dispatch(int width, int height) const {
  const auto& gl = context_->gl();
  gl.UseProgram(program_.id());
  const auto groups = [](int n, GLint local) { return static_cast<GLuint>((n + local - 1) / local); };
  if (census_) {
    const int g[2] = {static_cast<int>(groups(width, local_size_[0])), static_cast<int>(groups(height, local_size_[1]))};
    run_counted("dispatch", g, [&] { gl.DispatchCompute(g[0], g[1], 1); });
  } else {
    run("dispatch", [&] { gl.DispatchCompute(groups(width, local_size_[0]), groups(height, local_size_[1]), 1); });
  }
  gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                   GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  context_->throw_if_gl_error(name_ + ": dispatch");
}

void ComputeProgram::dispatch_indirect(const GlObject& buffer) const {
  const auto& gl = context_->gl();
  gl.MemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  gl.UseProgram(program_.id());
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffer.id());
  if (census_) {  // the group counts the GPU wrote, read back to size the count buffer
    GLuint wrote[3] = {0, 0, 0};
    read_buffer(*context_, buffer, 0, sizeof wrote, wrote);
    const int g[2] = {static_cast<int>(wrote[0]), static_cast<int>(wrote[1] * wrote[2])};
    run_counted("indirect dispatch", g, [&] { gl.DispatchComputeIndirect(0); });
  } else {
    run("indirect dispatch", [&] { gl.DispatchComputeIndirect(0); });
  }
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                   GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  context_->throw_if_gl_error(name_ + ": indirect dispatch");
}

Target driver_target(const Context& context) { return context.is_es() ? Target::es310 : Target::gl450; }

ComputeProgram compile_pass(const Context& context, const SourceTree& tree, const std::string& pass,
                            const std::vector<Define>& defines) {
  // The runner's own pass: from the root, never from the working directory.
  return ComputeProgram(context, pass,
                        standalone_source(flatten(tree, tree.locate_in_root(pass)), driver_target(context), defines),
                        defines);
}

GlObject link_raster_pass(const Context& context, const SourceTree& tree, const std::string& stem) {
  return link_raster_pass(context, tree, stem + ".vert", stem + ".frag", {});
}

GlObject link_raster_pass(const Context& context, const SourceTree& tree, const std::string& vertex,
                          const std::string& fragment, const std::vector<Define>& defines) {
  const Target target = driver_target(context);
  const ShaderSource vertex_source = standalone_source(flatten(tree, tree.locate_in_root(vertex)), target, defines);
  const ShaderSource fragment_source = standalone_source(flatten(tree, tree.locate_in_root(fragment)), target, defines);
  return link_program(context, fragment, {&vertex_source, &fragment_source});
}

}  // namespace pn
