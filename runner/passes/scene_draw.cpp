#include "passes/scene_draw.h"

#include <string>

#include "core/error.h"
#include "gl/texture.h"
#include "passes/scene_raster.h"

namespace pn {

// The program's output goes to draw buffer 0, which a new framebuffer maps to colour attachment 0.
static_assert(PN_SCENE_TARGET_LOCATION == 0, "draw_scene renders into draw buffer 0 (colour attachment 0)");

GlObject draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                    const float clear[4]) {
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
  constexpr GLuint kBufferSlot = 0;  // the vertex array's one buffer binding (not a shader binding)
  gl.VertexArrayVertexBuffer(vertex_array.id(), kBufferSlot, buffer.id(), 0, sizeof(glm::vec3));
  gl.EnableVertexArrayAttrib(vertex_array.id(), PN_SCENE_POSITION_LOCATION);
  gl.VertexArrayAttribFormat(vertex_array.id(), PN_SCENE_POSITION_LOCATION, 3, GL_FLOAT, GL_FALSE, 0);
  gl.VertexArrayAttribBinding(vertex_array.id(), PN_SCENE_POSITION_LOCATION, kBufferSlot);

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
