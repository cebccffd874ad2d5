// What one dispatch or draw reads and writes, bound for as long as this
// object lives and unbound when it goes: each pass binds everything it uses
// and leaves nothing bound, so a pass that forgets a binding reads nothing
// (zeros, which its check catches) instead of an earlier pass's data.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gl/objects.h"

namespace pn {

class PassBindings {
 public:
  // Throws Error(ExitCode::failed) naming what an earlier pass left bound (bound_resources).
  explicit PassBindings(const Context& context);
  ~PassBindings();
  PassBindings(const PassBindings&) = delete;
  PassBindings& operator=(const PassBindings&) = delete;

  void texture(GLuint unit, const GlObject& texture);
  // One level of a 2-D texture, or (layered) every layer of an array texture.
  void image(GLuint unit, const GlObject& texture, GLenum access, GLenum format, GLint level = 0, bool layered = false);
  void uniform_buffer(GLuint binding, const GlObject& buffer);
  void storage_buffer(GLuint binding, const GlObject& buffer);
  // A new std140 buffer holding `block` (a shared block, gl/std140.h), bound at Block::binding and
  // kept alive with the bindings.
  template <class Block>
  void uniform(const Block& block) {
    uniform_data(Block::binding, &block, sizeof block);
  }
  void uniform_data(GLuint binding, const void* data, std::size_t size);

 private:
  const Context* context_;
  std::vector<std::pair<GLuint, GLenum>> textures_;  // (unit, target)
  std::vector<GLuint> images_, uniforms_, storages_;
  std::vector<GlObject> owned_;
};

// What is still bound — "texture unit 3 (2D)", "image unit 2", "uniform buffer 7",
// "storage buffer 0" — on texture and image units and buffer bindings 0..15:
// empty after every pass that binds through PassBindings.
std::vector<std::string> bound_resources(const Context& context);

}  // namespace pn
