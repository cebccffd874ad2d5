// Drawing a scene's triangles into a float target with depth testing: the one
// raster path that the shadow map, the G-buffer, the surface pass and the
// shadow-map caches share.
#pragma once

#include <vector>

#include "core/texel_rect.h"
#include "gl/objects.h"
#include "gl/texture.h"
#include "scene/scene.h"

namespace pn {

// A scene's triangles() in one GPU vertex buffer (attribute PN_SCENE_POSITION_LOCATION, world
// positions), kept for many draws; the objects that moved are written again.
class SceneGeometry {
 public:
  SceneGeometry(const Context& context, const Scene& scene);
  int vertex_count() const { return vertex_count_; }
  // Writes the vertices of objects[o] for each o of `which` from `vertices` (a scene's triangles(), of
  // the layout the geometry was made with) — one write from the first to the last, the unchanged
  // vertices between them written again — or every vertex.
  void update(const std::vector<glm::vec3>& vertices, const std::vector<SceneObject>& objects, const std::vector<int>& which);
  void update_all(const std::vector<glm::vec3>& vertices);
  const GlObject& vertex_array() const { return vertex_array_; }

 private:
  const Context* context_;
  int vertex_count_;
  GlObject buffer_, vertex_array_;
};

// A run of vertices of a SceneGeometry: what one draw call draws.
struct VertexRun {
  int first = 0, count = 0;
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
  // Draws `runs` of `geometry` with `program` (output PN_SCENE_TARGET_LOCATION, nearest surface
  // kept), scissored to each rectangle in turn (unscissored for none given). Binds no resources:
  // the caller's PassBindings holds what the program reads.
  void draw(const GlObject& program, const SceneGeometry& geometry, const std::vector<VertexRun>& runs,
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

// Renders every triangle of `scene` with `program` into a new size×size float texture of
// `channels` channels cleared to `clear` (a SceneGeometry and a RasterTarget used once).
FloatTexture draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                        const float clear[4]);

}  // namespace pn
