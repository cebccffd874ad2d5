#include "gl/raster_target.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "passes/scene_raster.h"

namespace pn {

// The program's output goes to draw buffer 0, which a new framebuffer maps to colour attachment 0.
static_assert(PN_SCENE_TARGET_LOCATION == 0, "a raster target renders into draw buffer 0 (colour attachment 0)");

TriangleBuffer::TriangleBuffer(const Context& context, const std::vector<glm::vec3>& vertices)
    : context_(&context), vertex_count_(static_cast<int>(vertices.size())) {
  const auto& gl = context.gl();
  // Bind-to-edit vertex state (GL 4.5 core and ES 3.1 alike): one tightly packed vec3 attribute.
  buffer_ = make_buffer(context, std::max<std::size_t>(vertices.size(), 1) * sizeof(glm::vec3), vertices.data(),
                        GL_DYNAMIC_DRAW);
  vertex_array_ = GlObject(context, GlKind::vertex_array);
  gl.BindVertexArray(vertex_array_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer_.id());
  gl.EnableVertexAttribArray(PN_SCENE_POSITION_LOCATION);
  gl.VertexAttribPointer(PN_SCENE_POSITION_LOCATION, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  gl.BindVertexArray(0);
}

void TriangleBuffer::write(const std::vector<glm::vec3>& vertices, std::size_t first, std::size_t count) {
  if (static_cast<int>(vertices.size()) != vertex_count_)
    throw Error("scene geometry: " + std::to_string(vertices.size()) + " vertices, expected " +
                std::to_string(vertex_count_) + " (the layout it was made with)");
  if (first + count > vertices.size()) throw Error("scene geometry: an object past the scene's vertices");
  if (count > 0) write_buffer(*context_, buffer_, first * sizeof(glm::vec3), count * sizeof(glm::vec3), &vertices[first]);
}

RasterTarget::RasterTarget(const Context& context, int size, int channels)
    : context_(&context), size_(size), texture_(make_float_texture(context, size, size, channels)),
      depth_(context, GlKind::renderbuffer), framebuffer_(context, GlKind::framebuffer) {
  const auto& gl = context.gl();
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
  gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("framebuffer " + std::to_string(size) + "x" + std::to_string(size) + " is incomplete", ExitCode::failed);
}

namespace {

// Runs `each` once unscissored (no rectangles) or once per non-empty rectangle with the scissor on it.
template <class Each>
void per_rect(const GladGLContext& gl, const std::vector<TexelRect>& rects, const Each& each) {
  if (rects.empty()) return each();
  gl.Enable(GL_SCISSOR_TEST);
  for (const TexelRect& r : rects) {
    if (r.empty()) continue;
    gl.Scissor(r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
    each();
  }
  gl.Disable(GL_SCISSOR_TEST);
}

}  // namespace

void RasterTarget::clear(const float clear[4], const std::vector<TexelRect>& rects) const {
  const auto& gl = context_->gl();
  const float one = 1.0f;
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  per_rect(gl, rects, [&] {
    gl.ClearBufferfv(GL_COLOR, 0, clear);
    gl.ClearBufferfv(GL_DEPTH, 0, &one);
  });
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  context_->throw_if_gl_error("clearing a raster target");
}

void RasterTarget::copy_from(const RasterTarget& source, const std::vector<TexelRect>& rects) const {
  const auto& gl = context_->gl();
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, source.framebuffer_.id());
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  const auto blit = [&](const TexelRect& r) {
    gl.BlitFramebuffer(r.x0, r.y0, r.x1, r.y1, r.x0, r.y0, r.x1, r.y1, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  };
  if (rects.empty()) blit(TexelRect::square(size_));
  for (const TexelRect& r : rects)
    if (!r.empty()) blit(intersection(r, TexelRect::square(size_)));
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  context_->throw_if_gl_error("copying between raster targets");
}

void RasterTarget::draw(const GlObject& program, const TriangleBuffer& triangles, const std::vector<VertexRun>& runs,
                        const std::vector<TexelRect>& rects) const {
  const auto& gl = context_->gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.Viewport(0, 0, size_, size_);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.UseProgram(program.id());
  gl.BindVertexArray(triangles.vertex_array().id());
  per_rect(gl, rects, [&] {
    for (const VertexRun& run : runs)
      if (run.count > 0) gl.DrawArrays(GL_TRIANGLES, run.first, run.count);
  });
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.Disable(GL_DEPTH_TEST);
  context_->throw_if_gl_error("drawing into a raster target");
}

void RasterTarget::draw_full_screen(const GlObject& program) const {
  const auto& gl = context_->gl();
  const GlObject no_vertices(*context_, GlKind::vertex_array);  // a core profile draws with a vertex array bound
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.Viewport(0, 0, size_, size_);
  gl.UseProgram(program.id());
  gl.BindVertexArray(no_vertices.id());
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  context_->throw_if_gl_error("drawing a full-screen triangle");
}

}  // namespace pn
