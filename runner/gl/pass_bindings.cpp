#include "gl/pass_bindings.h"

#include <algorithm>
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
  for (const auto& [unit, target] : textures_) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    gl.BindTexture(target, 0);
  }
  if (!textures_.empty()) gl.ActiveTexture(GL_TEXTURE0);
  for (GLuint unit : images_) gl.BindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
  for (GLuint b : uniforms_) gl.BindBufferBase(GL_UNIFORM_BUFFER, b, 0);
  for (GLuint b : storages_) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
}

// glActiveTexture + glBindTexture (GL 4.5's glBindTextureUnit is not in ES); the active unit is
// left at 0, where bind-to-edit (gl/texture.cpp) restores what it finds.
void PassBindings::texture(GLuint unit, const GlObject& texture) {
  const auto& gl = context_->gl();
  gl.ActiveTexture(GL_TEXTURE0 + unit);
  gl.BindTexture(texture.target(), texture.id());
  gl.ActiveTexture(GL_TEXTURE0);
  textures_.emplace_back(unit, texture.target());
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
  GlObject buffer = make_buffer(*context_, size, data);
  uniform_buffer(binding, buffer);
  owned_.push_back(std::move(buffer));
}

std::vector<std::string> bound_resources(const Context& context) {
  const auto& gl = context.gl();
  constexpr GLuint kUnits = 16;
  // Units and bindings past the context's limit do not exist (ES 3.1 asks for as few as 4 image
  // units and 4 storage-buffer bindings); querying them would be an error.
  const auto limit = [&](GLenum what) {
    GLint n = 0;
    gl.GetIntegerv(what, &n);
    return std::min(kUnits, static_cast<GLuint>(std::max(n, 0)));
  };
  std::vector<std::string> out;
  GLint active = 0;
  gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (GLuint unit = 0, units = limit(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS); unit < units; ++unit) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    for (const auto& [target, what] : {std::pair{GL_TEXTURE_BINDING_2D, " (2D)"}, {GL_TEXTURE_BINDING_2D_ARRAY, " (2D array)"}}) {
      GLint name = 0;
      gl.GetIntegerv(target, &name);
      if (name != 0) out.push_back("texture unit " + std::to_string(unit) + what);
    }
  }
  gl.ActiveTexture(static_cast<GLenum>(active));
  const auto indexed = [&](GLenum query, GLenum count, const char* what) {
    for (GLuint i = 0, n = limit(count); i < n; ++i) {
      GLint name = 0;
      gl.GetIntegeri_v(query, i, &name);
      if (name != 0) out.push_back(std::string(what) + " " + std::to_string(i));
    }
  };
  indexed(GL_IMAGE_BINDING_NAME, GL_MAX_IMAGE_UNITS, "image unit");
  indexed(GL_UNIFORM_BUFFER_BINDING, GL_MAX_UNIFORM_BUFFER_BINDINGS, "uniform buffer");
  indexed(GL_SHADER_STORAGE_BUFFER_BINDING, GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, "storage buffer");
  return out;
}

}  // namespace pn
