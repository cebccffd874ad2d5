#include "gl/objects.h"

#include <cstring>

#include "core/error.h"

namespace pn {

GlObject::GlObject(const Context& context, GlKind kind, GLenum target)
    : gl_(&context.gl()), kind_(kind), target_(target) {
  switch (kind) {
    case GlKind::texture: gl_->GenTextures(1, &id_); break;
    case GlKind::buffer: gl_->GenBuffers(1, &id_); break;
    case GlKind::shader: id_ = gl_->CreateShader(target); break;
    case GlKind::program: id_ = gl_->CreateProgram(); break;
    case GlKind::query: gl_->GenQueries(1, &id_); break;
    case GlKind::vertex_array: gl_->GenVertexArrays(1, &id_); break;
    case GlKind::framebuffer: gl_->GenFramebuffers(1, &id_); break;
    case GlKind::renderbuffer: gl_->GenRenderbuffers(1, &id_); break;
  }
}

void GlObject::release() {
  if (id_ == 0) return;
  switch (kind_) {
    case GlKind::texture: gl_->DeleteTextures(1, &id_); break;
    case GlKind::buffer: gl_->DeleteBuffers(1, &id_); break;
    case GlKind::shader: gl_->DeleteShader(id_); break;
    case GlKind::program: gl_->DeleteProgram(id_); break;
    case GlKind::query: gl_->DeleteQueries(1, &id_); break;
    case GlKind::vertex_array: gl_->DeleteVertexArrays(1, &id_); break;
    case GlKind::framebuffer: gl_->DeleteFramebuffers(1, &id_); break;
    case GlKind::renderbuffer: gl_->DeleteRenderbuffers(1, &id_); break;
  }
  id_ = 0;
}

GlObject make_buffer(const Context& context, std::size_t size, const void* data, GLenum usage) {
  GlObject buffer(context, GlKind::buffer);
  const auto& gl = context.gl();
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
  gl.BufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(size), data, usage);
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, 0);
  context.throw_if_gl_error("allocating a buffer of " + std::to_string(size) + " bytes");
  return buffer;
}

void write_buffer(const Context& context, const GlObject& buffer, std::size_t offset, std::size_t size, const void* data) {
  const auto& gl = context.gl();
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
  gl.BufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(size), data);
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, 0);
  context.throw_if_gl_error("writing a buffer");
}

void read_buffer(const Context& context, const GlObject& buffer, std::size_t offset, std::size_t size, void* data) {
  const auto& gl = context.gl();
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.BindBuffer(GL_COPY_READ_BUFFER, buffer.id());
  const void* mapped = gl.MapBufferRange(GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset),
                                         static_cast<GLsizeiptr>(size), GL_MAP_READ_BIT);
  if (mapped != nullptr) {
    std::memcpy(data, mapped, size);
    gl.UnmapBuffer(GL_COPY_READ_BUFFER);
  }
  gl.BindBuffer(GL_COPY_READ_BUFFER, 0);
  context.throw_if_gl_error("reading a buffer back");
  if (mapped == nullptr) throw Error("reading a buffer back: glMapBufferRange failed", ExitCode::failed);
}

}  // namespace pn
