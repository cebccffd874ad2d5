#include "cache/object_motion.h"

#include <algorithm>
#include <cmath>

namespace pn {

TexelRect map_bounds(const Scene& scene, const glm::mat4& light_view_projection, const glm::vec3* vertices, int count) {
  const int n = scene.light.map_size;
  if (count <= 0) return {};
  float lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (int i = 0; i < count; ++i) {
    const glm::vec4 c = light_view_projection * glm::vec4(vertices[i], 1.0f);
    if (!(c.w > 1e-6f)) return TexelRect::square(n);
    // Window coordinates in texels, as the rasteriser's viewport maps them.
    const float x = (c.x / c.w * 0.5f + 0.5f) * static_cast<float>(n);
    const float y = (c.y / c.w * 0.5f + 0.5f) * static_cast<float>(n);
    lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
  }
  const auto texel = [&](float v) { return static_cast<int>(std::clamp(std::floor(v), -2.0f, static_cast<float>(n) + 2.0f)); };
  const TexelRect r{texel(lo_x) - 1, texel(lo_y) - 1, texel(hi_x) + 2, texel(hi_y) + 2};
  return intersection(r, TexelRect::square(n));
}

std::vector<SceneObject> scene_objects(const Scene& scene, int vertex_count) {
  if (!scene.objects.empty()) return scene.objects;
  return {SceneObject{0, vertex_count, glm::mat4(1.0f)}};
}

bool ObjectMotion::track(const Scene& scene, const std::vector<glm::vec3>& vertices) {
  const std::vector<SceneObject> objects = scene_objects(scene, static_cast<int>(vertices.size()));
  const glm::mat4 light = scene.light_projection() * scene.light_view();
  bool same = map_size_ == scene.light.map_size && light_ == light && objects.size() == objects_.size();
  for (size_t i = 0; same && i < objects.size(); ++i)
    same = objects[i].first_vertex == objects_[i].first_vertex && objects[i].vertex_count == objects_[i].vertex_count;
  const auto bounds = [&](const SceneObject& o) {
    return map_bounds(scene, light, vertices.data() + o.first_vertex, o.vertex_count);
  };
  if (!same) {
    frames_.assign(objects.size(), {});
    for (size_t i = 0; i < objects.size(); ++i) frames_[i].bounds = frames_[i].old_bounds = bounds(objects[i]);
  } else {
    for (size_t i = 0; i < objects.size(); ++i) {
      ObjectFrame& f = frames_[i];
      f.was_dynamic = f.dynamic;
      f.old_bounds = f.bounds;
      f.dynamic = objects[i].transform != objects_[i].transform;
      if (f.dynamic) f.bounds = bounds(objects[i]);
    }
  }
  objects_ = objects;
  light_ = light;
  map_size_ = scene.light.map_size;
  return same;
}

}  // namespace pn
