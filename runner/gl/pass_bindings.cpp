#include "gl/pass_bindings.h"

#include <utility>

#include "core/error.h"

namespace pn {

PassBindings::PassBindings(const Context& context) : context_(&context) {
  const std::vector<std::string> bound = bound_resources(context);
  if (bound.empty()) return;
  std::string list;
  for (const std::string& b : bound) list += (list.empty() ? "" : ", ") + b;
  throw Error("a pass starts with " + list + " still bound by an earlier one: expected every pass to bind through "
              "PassBindings (runner/gl/pass_bindings.h), which unbinds what it bound",
              ExitCode::failed);
}

PassBindings::~PassBindings() {
  const auto& gl = context_->gl();
  for (GLuint unit : textures_) gl.BindTextureUnit(unit, 0);
  for (GLuint unit : images_) gl.BindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
  for (GLuint b : uniforms_) gl.BindBufferBase(GL_UNIFORM_BUFFER, b, 0);
  for (GLuint b : storages_) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
}

void PassBindings::texture(GLuint unit, const GlObject& texture) {
  context_->gl().BindTextureUnit(unit, texture.id());
  textures_.push_back(unit);
}

void PassBindings::image(GLuint unit, const GlObject& texture, GLenum access, GLenum format, GLint level, bool layered) {
  context_->gl().BindImageTexture(unit, texture.id(), level, layered ? GL_TRUE : GL_FALSE, 0, access, format);
  images_.push_back(unit);
}

void PassBindings::uniform_buffer(GLuint binding, const GlObject& buffer) {
  context_->gl().BindBufferBase(GL_UNIFORM_BUFFER, binding, buffer.id());
  uniforms_.push_back(binding);
}

void PassBindings::storage_buffer(GLuint binding, const GlObject& buffer) {
  context_->gl().BindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer.id());
  storages_.push_back(binding);
}

void PassBindings::uniform_data(GLuint binding, const void* data, std::size_t size) {
  GlObject buffer(*context_, GlKind::buffer);
  context_->gl().NamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(size), data, 0);
  uniform_buffer(binding, buffer);
  owned_.push_back(std::move(buffer));
}

std::vector<std::string> bound_resources(const Context& context) {
  const auto& gl = context.gl();
  constexpr GLuint kUnits = 16;
  std::vector<std::string> out;
  GLint active = 0;
  gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (GLuint unit = 0; unit < kUnits; ++unit) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    for (const auto& [target, what] : {std::pair{GL_TEXTURE_BINDING_2D, " (2D)"}, {GL_TEXTURE_BINDING_2D_ARRAY, " (2D array)"}}) {
      GLint name = 0;
      gl.GetIntegerv(target, &name);
      if (name != 0) out.push_back("texture unit " + std::to_string(unit) + what);
    }
  }
  gl.ActiveTexture(static_cast<GLenum>(active));
  const auto indexed = [&](GLenum query, const char* what) {
    for (GLuint i = 0; i < kUnits; ++i) {
      GLint name = 0;
      gl.GetIntegeri_v(query, i, &name);
      if (name != 0) out.push_back(std::string(what) + " " + std::to_string(i));
    }
  };
  indexed(GL_IMAGE_BINDING_NAME, "image unit");
  indexed(GL_UNIFORM_BUFFER_BINDING, "uniform buffer");
  indexed(GL_SHADER_STORAGE_BUFFER_BINDING, "storage buffer");
  return out;
}

}  // namespace pn
