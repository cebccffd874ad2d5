#include "passes/scene_draw.h"

#include <algorithm>

namespace pn {

SceneGeometry::SceneGeometry(const Context& context, const Scene& scene) : TriangleBuffer(context, scene.triangles()) {}

void SceneGeometry::update(const std::vector<glm::vec3>& vertices, const std::vector<SceneObject>& objects,
                           const std::vector<int>& which) {
  if (which.empty()) return write(vertices, 0, 0);  // checks the layout
  size_t first = vertices.size(), end = 0;
  for (int o : which) {
    const SceneObject& object = objects.at(static_cast<size_t>(o));
    first = std::min(first, static_cast<size_t>(object.first_vertex));
    end = std::max(end, static_cast<size_t>(object.first_vertex) + static_cast<size_t>(object.vertex_count));
  }
  write(vertices, first, end - first);
}

void SceneGeometry::update_all(const std::vector<glm::vec3>& vertices) { write(vertices, 0, vertices.size()); }

FloatTexture draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                        const float clear[4]) {
  const SceneGeometry geometry(context, scene);
  RasterTarget target(context, size, channels);
  target.clear(clear);
  target.draw(program, geometry, {{0, geometry.vertex_count()}});
  return target.release_texture();
}

}  // namespace pn
