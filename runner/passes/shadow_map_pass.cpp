#include "passes/shadow_map_pass.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

#include "core/error.h"
#include "gl/texture.h"
#include "shader/flatten.h"

namespace pn {

ShadowMapRenderer::ShadowMapRenderer(const Context& context, const SourceTree& tree) : context_(&context) {
  const ShaderSource vertex = standalone_source(flatten(tree, "passes/shadow_depth.vert"), Target::gl450);
  const ShaderSource fragment = standalone_source(flatten(tree, "passes/shadow_depth.frag"), Target::gl450);
  program_ = link_program(context, "passes/shadow_depth", {&vertex, &fragment});
}

GlObject ShadowMapRenderer::render(const Scene& scene) const {
  const int n = scene.light.map_size;
  const auto& gl = context_->gl();
  GlObject target = make_float_texture(*context_, n, n, 1);
  GlObject depth(*context_, GlKind::renderbuffer);
  gl.NamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, n, n);
  GlObject framebuffer(*context_, GlKind::framebuffer);
  gl.NamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  if (gl.CheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("shadow map framebuffer " + std::to_string(n) + "x" + std::to_string(n) + " is incomplete",
                ExitCode::failed);

  const std::vector<glm::vec3> vertices = scene.triangles();
  GlObject buffer(*context_, GlKind::buffer);
  gl.NamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)), vertices.data(), 0);
  GlObject vertex_array(*context_, GlKind::vertex_array);
  gl.VertexArrayVertexBuffer(vertex_array.id(), 0, buffer.id(), 0, sizeof(glm::vec3));
  gl.EnableVertexArrayAttrib(vertex_array.id(), 0);
  gl.VertexArrayAttribFormat(vertex_array.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  gl.VertexArrayAttribBinding(vertex_array.id(), 0, 0);

  struct {
    float view[16], projection[16];
  } block{};
  const glm::mat4 view = scene.light_view(), projection = scene.light_projection();
  std::copy_n(glm::value_ptr(view), 16, block.view);
  std::copy_n(glm::value_ptr(projection), 16, block.projection);
  GlObject params = bind_uniform_buffer(*context_, 0, &block, sizeof block);

  const float far[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  const float one = 1.0f;
  gl.ClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, far);
  gl.ClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &one);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  gl.Viewport(0, 0, n, n);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);
  gl.UseProgram(program_.id());
  gl.BindVertexArray(vertex_array.id());
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.Disable(GL_DEPTH_TEST);
  context_->throw_if_gl_error("rendering the shadow map of scene '" + scene.name + "'");
  return target;
}

}  // namespace pn
