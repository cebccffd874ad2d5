// Move-only owners of GL names (magnum's model): each deletes its name in the
// destructor through the function table of the context that made it, so no
// name outlives its context and no check leaks objects into the next.
#pragma once

#include <utility>

#include "gl/context.h"

namespace pn {

// texture_view: a texture name that glGenTextures reserves without creating the object, as
// glTextureView requires (texture.h's make_texture_view); released like a texture.
enum class GlKind { texture, texture_view, buffer, shader, program, query, vertex_array, framebuffer, renderbuffer };

class GlObject {
 public:
  GlObject() = default;
  GlObject(const Context& context, GlKind kind, GLenum target = 0);
  ~GlObject() { release(); }
  GlObject(GlObject&& other) noexcept { *this = std::move(other); }
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      release();
      gl_ = std::exchange(other.gl_, nullptr);
      kind_ = other.kind_;
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint id() const { return id_; }

 private:
  void release();
  const GladGLContext* gl_ = nullptr;
  GlKind kind_ = GlKind::texture;
  GLuint id_ = 0;
};

}  // namespace pn
