#include "gl/objects.h"

namespace pn {

// `target` is the texture target, the shader stage or the query target.
GlObject::GlObject(const Context& context, GlKind kind, GLenum target) : gl_(&context.gl()), kind_(kind) {
  switch (kind) {
    case GlKind::texture: gl_->CreateTextures(target, 1, &id_); break;
    case GlKind::texture_view: gl_->GenTextures(1, &id_); break;
    case GlKind::buffer: gl_->CreateBuffers(1, &id_); break;
    case GlKind::shader: id_ = gl_->CreateShader(target); break;
    case GlKind::program: id_ = gl_->CreateProgram(); break;
    case GlKind::query: gl_->CreateQueries(target, 1, &id_); break;
    case GlKind::vertex_array: gl_->CreateVertexArrays(1, &id_); break;
    case GlKind::framebuffer: gl_->CreateFramebuffers(1, &id_); break;
    case GlKind::renderbuffer: gl_->CreateRenderbuffers(1, &id_); break;
  }
}

void GlObject::release() {
  if (id_ == 0) return;
  switch (kind_) {
    case GlKind::texture:
    case GlKind::texture_view: gl_->DeleteTextures(1, &id_); break;
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

}  // namespace pn
