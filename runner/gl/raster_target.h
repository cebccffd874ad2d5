// The GL raster path: triangles in one vertex buffer, and a float target with its own depth
// buffer, drawn into, cleared and copied inside rectangles, or covered by a full-screen fragment
// pass. gl/query_device_gl.cpp runs every raster pass of the device seam through it (the shadow
// map, the G-buffer, the surface pass, the shadow-map caches' kept targets, the techniques'
// fragment shaders).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "core/texel_rect.h"
#include "gl/objects.h"
#include "gl/texture.h"

namespace pn {

// Triangle corners (world positions, attribute PN_SCENE_POSITION_LOCATION) in one GPU vertex
// buffer, kept for many draws.
class TriangleBuffer {
 public:
  TriangleBuffer(const Context& context, const std::vector<glm::vec3>& vertices);
  int vertex_count() const { return vertex_count_; }
  // Writes vertices [first, first + count) from `vertices` (the whole list, of vertex_count()).
  void write(const std::vector<glm::vec3>& vertices, std::size_t first, std::size_t count);
  const GlObject& vertex_array() const { return vertex_array_; }

 private:
  const Context* context_;
  int vertex_count_;
  GlObject buffer_, vertex_array_;
};

// A size×size float texture of `channels` channels with its own depth buffer, drawn into frame
// after frame. Rows from the framebuffer's bottom (TexelRect rows likewise).
class RasterTarget {
 public:
  RasterTarget(const Context& context, int size, int channels);
  int size() const { return size_; }
  const GlObject& texture() const { return texture_; }
  FloatTexture release_texture() { return std::move(texture_); }

  // Colour to `clear`, depth to the far plane, inside each rectangle (the whole target for none given).
  void clear(const float clear[4], const std::vector<TexelRect>& rects = {}) const;
  // Colour and depth of `source` (the same size and channels) copied into this target inside each
  // rectangle (everywhere for none given), bit for bit.
  void copy_from(const RasterTarget& source, const std::vector<TexelRect>& rects = {}) const;
  // Draws `runs` of `triangles` with `program` (output PN_SCENE_TARGET_LOCATION, nearest surface
  // kept), scissored to each rectangle in turn (unscissored for none given). Binds no resources:
  // the caller's PassBindings holds what the program reads.
  void draw(const GlObject& program, const TriangleBuffer& triangles, const std::vector<VertexRun>& runs,
            const std::vector<TexelRect>& rects = {}) const;
  // Draws one triangle covering the target with `program` (passes/full_screen.vert's vertex
  // stage: no vertex buffer), no depth test: a full-screen fragment pass.
  void draw_full_screen(const GlObject& program) const;

 private:
  const Context* context_;
  int size_;
  FloatTexture texture_;
  GlObject depth_, framebuffer_;
};

}  // namespace pn
