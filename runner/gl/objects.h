// Move-only owners of GL names (magnum's model): each deletes its name in the
// destructor through the function table of the context that made it, so no
// name outlives its context and no check leaks objects into the next.
//
// Names come from glGen* (and glCreateShader/Program), not GL 4.5's glCreate*: the object is
// made when first bound, as GL 4.5 core and OpenGL ES 3.1 both do, and every edit binds it
// (bind-to-edit, the subset both APIs share; gl/texture.h, make_buffer below).
#pragma once

#include <cstddef>
#include <utility>

#include "gl/context.h"

namespace pn {

enum class GlKind { texture, buffer, shader, program, query, vertex_array, framebuffer, renderbuffer };

class GlObject {
 public:
  GlObject() = default;
  // `target` is a texture's target (GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY: where it is bound), a
  // shader's stage, or a query's target.
  GlObject(const Context& context, GlKind kind, GLenum target = 0);
  ~GlObject() { release(); }
  GlObject(GlObject&& other) noexcept { *this = std::move(other); }
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      release();
      gl_ = std::exchange(other.gl_, nullptr);
      kind_ = other.kind_;
      target_ = other.target_;
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }

 private:
  void release();
  const GladGLContext* gl_ = nullptr;
  GlKind kind_ = GlKind::texture;
  GLenum target_ = 0;
  GLuint id_ = 0;
};

// A buffer of `size` bytes holding `data` (undefined bytes where it is null), filled with
// glBufferData through GL_COPY_WRITE_BUFFER, a target no pass binds; `usage` is the hint.
GlObject make_buffer(const Context& context, std::size_t size, const void* data, GLenum usage = GL_STATIC_DRAW);
// Replaces `size` bytes at `offset` of `buffer` (glBufferSubData, same target).
void write_buffer(const Context& context, const GlObject& buffer, std::size_t offset, std::size_t size, const void* data);
// Reads `size` bytes at `offset` back (glMapBufferRange, on both APIs), after the writes of
// earlier commands.
void read_buffer(const Context& context, const GlObject& buffer, std::size_t offset, std::size_t size, void* data);

}  // namespace pn
