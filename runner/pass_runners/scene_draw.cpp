#include "pass_runners/scene_draw.h"

#include <algorithm>

namespace pn {

SceneGeometry::SceneGeometry(const QueryDevice& device, const Scene& scene)
    : device_(&device), vertices_(device.make_vertices(scene.triangles())) {}

void SceneGeometry::update(const std::vector<glm::vec3>& vertices, const std::vector<SceneObject>& objects,
                           const std::vector<int>& which) {
  if (which.empty()) return device_->write_vertices(*vertices_, vertices, 0, 0);  // checks the layout
  size_t first = vertices.size(), end = 0;
  for (int o : which) {
    const SceneObject& object = objects.at(static_cast<size_t>(o));
    first = std::min(first, static_cast<size_t>(object.first_vertex));
    end = std::max(end, static_cast<size_t>(object.first_vertex) + static_cast<size_t>(object.vertex_count));
  }
  device_->write_vertices(*vertices_, vertices, first, end - first);
}

void SceneGeometry::update_all(const std::vector<glm::vec3>& vertices) {
  device_->write_vertices(*vertices_, vertices, 0, vertices.size());
}

}  // namespace pn
