#include "passes/scene_draw.h"

#include <string>

#include "core/error.h"
#include "gl/compute_program.h"
#include "gl/texture.h"

namespace pn {

GlObject draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                    const float clear[4], const void* block, std::size_t block_size) {
  const auto& gl = context.gl();
  GlObject target = make_float_texture(context, size, size, channels);
  GlObject depth(context, GlKind::renderbuffer);
  gl.NamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, size, size);
  GlObject framebuffer(context, GlKind::framebuffer);
  gl.NamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  if (gl.CheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("framebuffer " + std::to_string(size) + "x" + std::to_string(size) + " is incomplete", ExitCode::failed);

  const std::vector<glm::vec3> vertices = scene.triangles();
  GlObject buffer(context, GlKind::buffer);
  gl.NamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)), vertices.data(), 0);
  GlObject vertex_array(context, GlKind::vertex_array);
  gl.VertexArrayVertexBuffer(vertex_array.id(), 0, buffer.id(), 0, sizeof(glm::vec3));
  gl.EnableVertexArrayAttrib(vertex_array.id(), 0);
  gl.VertexArrayAttribFormat(vertex_array.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  gl.VertexArrayAttribBinding(vertex_array.id(), 0, 0);
  GlObject params = bind_uniform_buffer(context, 0, block, block_size);

  const float one = 1.0f;
  gl.ClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);
  gl.ClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &one);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  gl.Viewport(0, 0, size, size);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.UseProgram(program.id());
  gl.BindVertexArray(vertex_array.id());
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.Disable(GL_DEPTH_TEST);
  context.throw_if_gl_error("drawing scene '" + scene.name + "'");
  return target;
}

}  // namespace pn
