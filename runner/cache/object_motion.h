// Which objects of a scene moved (seed 001's motion-state tracking): each
// frame's Scene::objects compared with the previous frame's — an object whose
// transform changed is dynamic this frame, static otherwise — and where each
// lies in the shadow map, as a rectangle of texels.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/texel_rect.h"
#include "scene/scene.h"

namespace pn {

struct ObjectFrame {
  bool dynamic = false;      // its transform differs from the previous frame's
  bool was_dynamic = false;  // it was dynamic in the previous frame
  TexelRect bounds;          // the texels it may cover this frame
  TexelRect old_bounds;      // … and in the previous frame
};

// The rectangle of an n×n map (n = scene.light.map_size) that holds every texel whose centre a
// triangle of `vertices` may cover: the projected vertices' bounds, one texel wider each way, clipped
// to the map; the whole map when a vertex lies at or behind the light's plane (its projection is
// not bounded by the vertices'), empty when they all project outside.
TexelRect map_bounds(const Scene& scene, const glm::mat4& light_view_projection, const glm::vec3* vertices, int count);

class ObjectMotion {
 public:
  // This frame's objects (a scene without Scene::objects is one object). Returns false when there
  // is no previous frame of the same layout (objects' vertex runs, light, map size): then every
  // object is static and new, and a cache must draw everything.
  bool track(const Scene& scene, const std::vector<glm::vec3>& vertices);
  const std::vector<ObjectFrame>& objects() const { return frames_; }
  const std::vector<SceneObject>& layout() const { return objects_; }

 private:
  std::vector<SceneObject> objects_;  // the previous frame's
  glm::mat4 light_{0.0f};
  int map_size_ = 0;
  std::vector<ObjectFrame> frames_;
};

// Scene::objects, or one object of every vertex with the identity transform.
std::vector<SceneObject> scene_objects(const Scene& scene, int vertex_count);

}  // namespace pn
