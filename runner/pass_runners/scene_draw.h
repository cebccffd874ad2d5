// A scene's triangles in a vertex buffer kept on the device (QueryDevice's kept raster path),
// for the shadow-map caches that draw them frame after frame.
#pragma once

#include <memory>
#include <vector>

#include "device/query_device.h"
#include "scene/scene.h"

namespace pn {

// A scene's triangles() in one vertex buffer on a device, kept for many draws; the objects that
// moved are written again.
class SceneGeometry {
 public:
  SceneGeometry(const QueryDevice& device, const Scene& scene);
  int vertex_count() const { return vertices_->count(); }
  const DeviceVertices& vertices() const { return *vertices_; }
  // Writes the vertices of objects[o] for each o of `which` from `vertices` (a scene's triangles(), of
  // the layout the geometry was made with) — one write from the first to the last, the unchanged
  // vertices between them written again — or every vertex.
  void update(const std::vector<glm::vec3>& vertices, const std::vector<SceneObject>& objects, const std::vector<int>& which);
  void update_all(const std::vector<glm::vec3>& vertices);

 private:
  const QueryDevice* device_;
  std::unique_ptr<DeviceVertices> vertices_;
};

}  // namespace pn
