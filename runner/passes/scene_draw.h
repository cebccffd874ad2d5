// A scene's triangles drawn into a float target with depth testing, through the one raster path
// (gl/raster_target.h) that the shadow map, the G-buffer, the surface pass and the shadow-map
// caches share.
#pragma once

#include <vector>

#include "core/texel_rect.h"
#include "gl/raster_target.h"
#include "scene/scene.h"

namespace pn {

// A scene's triangles() in one GPU vertex buffer, kept for many draws; the objects that moved are
// written again.
class SceneGeometry : public TriangleBuffer {
 public:
  SceneGeometry(const Context& context, const Scene& scene);
  // Writes the vertices of objects[o] for each o of `which` from `vertices` (a scene's triangles(), of
  // the layout the geometry was made with) — one write from the first to the last, the unchanged
  // vertices between them written again — or every vertex.
  void update(const std::vector<glm::vec3>& vertices, const std::vector<SceneObject>& objects, const std::vector<int>& which);
  void update_all(const std::vector<glm::vec3>& vertices);
};

// Renders every triangle of `scene` with `program` into a new size×size float texture of
// `channels` channels cleared to `clear` (a SceneGeometry and a RasterTarget used once).
FloatTexture draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                        const float clear[4]);

}  // namespace pn
