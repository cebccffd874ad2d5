// The little GL plumbing the example needs: a move-only owner for GL names,
// programs compiled from several source strings, and a GL error check.
#pragma once

#include <glad/gl.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace example {

// One GL name (texture, buffer, framebuffer, vertex array, program), deleted
// with it: no name outlives the scope that made it.
class GlName {
 public:
  using Delete = void (*)(GLuint);
  GlName(GLuint id, Delete del) : id_(id), delete_(del) {}
  GlName(GlName&& other) noexcept : id_(std::exchange(other.id_, 0)), delete_(other.delete_) {}
  GlName& operator=(GlName&& other) noexcept {
    std::swap(id_, other.id_), std::swap(delete_, other.delete_);
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  ~GlName() {
    if (id_ != 0) delete_(id_);
  }
  GLuint id() const { return id_; }

 private:
  GLuint id_;
  Delete delete_;
};

GlName make_texture(GLenum format, int width, int height, int levels = 1);  // immutable storage, NEAREST filtering
GlName make_framebuffer(std::initializer_list<std::pair<GLenum, GLuint>> attachments);  // throws when incomplete
GlName make_buffer(const void* data, std::size_t bytes);
GlName make_vertex_array(const GlName& buffer);  // attribute EX_POSITION_ATTRIBUTE: vec3, tightly packed

// One source string a piece, in order: glShaderSource takes several, so an
// engine's header and a generated bundle need no text pasting. Throws
// std::runtime_error with the driver's log, naming `what`.
struct ShaderStage {
  GLenum type;
  std::vector<const char*> pieces;
};
GlName compile_program(const std::string& what, std::initializer_list<ShaderStage> stages);

// Throws std::runtime_error naming `step` when GL recorded an error.
void check_gl(const char* step);

}  // namespace example
