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

}  // namespace

ComputeProgram::ComputeProgram(const Context& context, const std::string& name, const ShaderSource& source)
    : context_(&context), name_(name), program_(context, GlKind::program) {
  const auto& gl = context.gl();
  GlObject shader(context, GlKind::shader, GL_COMPUTE_SHADER);
  const std::string driver_text = source.driver_text();
  const char* text = driver_text.c_str();
  gl.ShaderSource(shader.id(), 1, &text, nullptr);
  gl.CompileShader(shader.id());
  GLint ok = 0;
  gl.GetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  auto log_of = [&](GLuint id, bool is_program) {
    GLint length = 0;
    is_program ? gl.GetProgramiv(id, GL_INFO_LOG_LENGTH, &length) : gl.GetShaderiv(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    is_program ? gl.GetProgramInfoLog(id, length, nullptr, log.data())
               : gl.GetShaderInfoLog(id, length, nullptr, log.data());
    return std::string(log.c_str());
  };
  const std::string entry = source.files.empty() ? name : source.files.front();
  const LocationMap by_physical_line = [&](int, int line) { return source.origin_of_line(line); };
  if (!ok) {
    const std::string log = log_of(shader.id(), false);
    context.discard_gl_errors();  // the mapped log below says it better
    throw Error(name + ": the GL driver rejected the pass:\n" +
                    first_lines(parse_info_log(log, by_physical_line, entry), log),
                ExitCode::failed);
  }
  gl.AttachShader(program_.id(), shader.id());
  gl.LinkProgram(program_.id());
  gl.GetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    context.discard_gl_errors();
    throw Error(name + ": the GL driver could not link the pass: " + log_of(program_.id(), true), ExitCode::failed);
  }
  gl.GetProgramiv(program_.id(), GL_COMPUTE_WORK_GROUP_SIZE, local_size_);
  context.throw_if_gl_error(name + ": building the program");
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

ComputeProgram compile_pass(const Context& context, const SourceTree& tree, const std::string& pass,
                            const std::vector<Define>& defines) {
  return ComputeProgram(context, pass, standalone_source(flatten(tree, pass), Target::gl450, defines));
}

GlObject bind_uniform_buffer(const Context& context, GLuint binding, const void* data, size_t size) {
  GlObject buffer(context, GlKind::buffer);
  context.gl().NamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(size), data, 0);
  context.gl().BindBufferBase(GL_UNIFORM_BUFFER, binding, buffer.id());
  context.throw_if_gl_error("uniform buffer");
  return buffer;
}

}  // namespace pn
