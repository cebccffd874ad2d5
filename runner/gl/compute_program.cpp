#include "gl/compute_program.h"

#include <vector>

#include "core/error.h"
#include "shader/diagnostic.h"
#include "shader/flatten.h"

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

ComputeProgram::ComputeProgram(const Context& context, const std::string& name, const ShaderSource& source)
    : context_(&context), name_(name), program_(link_program(context, name, {&source})) {
  context.gl().GetProgramiv(program_.id(), GL_COMPUTE_WORK_GROUP_SIZE, local_size_);
}

void ComputeProgram::dispatch(int width, int height) const {
  const auto& gl = context_->gl();
  gl.UseProgram(program_.id());
  const auto groups = [](int n, GLint local) { return static_cast<GLuint>((n + local - 1) / local); };
  gl.DispatchCompute(groups(width, local_size_[0]), groups(height, local_size_[1]), 1);
  gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                   GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  context_->throw_if_gl_error(name_ + ": dispatch");
}

void ComputeProgram::dispatch_indirect(const GlObject& buffer) const {
  const auto& gl = context_->gl();
  gl.MemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  gl.UseProgram(program_.id());
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffer.id());
  gl.DispatchComputeIndirect(0);
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                   GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  context_->throw_if_gl_error(name_ + ": indirect dispatch");
}

ComputeProgram compile_pass(const Context& context, const SourceTree& tree, const std::string& pass,
                            const std::vector<Define>& defines) {
  return ComputeProgram(context, pass, standalone_source(flatten(tree, pass), Target::gl450, defines));
}

GlObject link_raster_pass(const Context& context, const SourceTree& tree, const std::string& stem) {
  const ShaderSource vertex = standalone_source(flatten(tree, stem + ".vert"), Target::gl450);
  const ShaderSource fragment = standalone_source(flatten(tree, stem + ".frag"), Target::gl450);
  return link_program(context, stem, {&vertex, &fragment});
}

}  // namespace pn
