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
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth.id());
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
  gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
  GlObject framebuffer(context, GlKind::framebuffer);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    throw Error("framebuffer " + std::to_string(size) + "x" + std::to_string(size) + " is incomplete", ExitCode::failed);
  }

  // Bind-to-edit vertex state (GL 4.5 core and ES 3.1 alike): one tightly packed vec3 attribute.
  const std::vector<glm::vec3> vertices = scene.triangles();
  const GlObject buffer = make_buffer(context, vertices.size() * sizeof(glm::vec3), vertices.data());
  GlObject vertex_array(context, GlKind::vertex_array);
  gl.BindVertexArray(vertex_array.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
  gl.EnableVertexAttribArray(PN_SCENE_POSITION_LOCATION);
  gl.VertexAttribPointer(PN_SCENE_POSITION_LOCATION, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  gl.BindVertexArray(0);

  const float one = 1.0f;
  gl.ClearBufferfv(GL_COLOR, 0, clear);
  gl.ClearBufferfv(GL_DEPTH, 0, &one);
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
