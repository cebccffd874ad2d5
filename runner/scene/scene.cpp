#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/seeded_random.h"

namespace pn {

glm::mat4 Scene::light_view() const {
  return glm::lookAt(light_position, light_position + glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
}

glm::mat4 Scene::light_projection() const {
  return glm::perspective(static_cast<float>(light.fov_radians), 1.0f, static_cast<float>(light.near_plane),
                          static_cast<float>(light.far_plane));
}

std::vector<glm::vec3> Scene::triangles() const {
  std::vector<glm::vec3> out;
  for (const Box& b : boxes) {
    const glm::vec3 c[8] = {{b.lo.x, b.lo.y, b.lo.z}, {b.hi.x, b.lo.y, b.lo.z}, {b.hi.x, b.hi.y, b.lo.z},
                            {b.lo.x, b.hi.y, b.lo.z}, {b.lo.x, b.lo.y, b.hi.z}, {b.hi.x, b.lo.y, b.hi.z},
                            {b.hi.x, b.hi.y, b.hi.z}, {b.lo.x, b.hi.y, b.hi.z}};
    // Two triangles per face, counter-clockwise seen from outside.
    static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (const auto& f : faces)
      for (int i : {0, 1, 2, 0, 2, 3}) out.push_back(c[f[i]]);
  }
  return out;
}

Scene make_scene(const fixtures::SceneFixture& fixture, int shadow_map_size) {
  using namespace fixtures;
  Scene scene;
  scene.name = fixture.name;
  scene.light = {fixture.light_width, kLightNear, kLightFar, kLightFovDegrees * 3.14159265358979 / 180.0, shadow_map_size};
  scene.light.validate();
  scene.light_position = {0.0f, kLightHeight, 0.0f};
  const float g = kGroundHalfWidth;
  scene.boxes.push_back({{-g, -1.0f, -g}, {g, 0.0f, g}});
  switch (fixture.kind) {
    case SceneKind::random_boxes: {
      SeededRandom random(fixture.seed);
      for (int k = 0; k < fixture.count; ++k) {
        const float w = random.uniform_float(0.4f, 1.6f), d = random.uniform_float(0.4f, 1.6f);
        const float h = random.uniform_float(0.5f, 3.0f);
        const float x = random.uniform_float(-7.0f, 7.0f), z = random.uniform_float(-7.0f, 7.0f);
        scene.boxes.push_back({{x - w / 2, 0.0f, z - d / 2}, {x + w / 2, h, z + d / 2}});
      }
      break;
    }
    case SceneKind::fence: {
      const float step = 12.0f / static_cast<float>(std::max(fixture.count - 1, 1));
      for (int k = 0; k < fixture.count; ++k) {
        const float x = -6.0f + step * static_cast<float>(k);
        scene.boxes.push_back({{x - 0.06f, 0.0f, -0.06f}, {x + 0.06f, 2.5f, 0.06f}});
      }
      for (float y : {1.0f, 2.0f}) scene.boxes.push_back({{-6.2f, y, -0.05f}, {6.2f, y + 0.12f, 0.05f}});
      break;
    }
    case SceneKind::tall_blocker:
      scene.boxes.push_back({{-1.0f, 0.0f, -1.0f}, {1.0f, 12.0f, 1.0f}});
      break;
  }
  return scene;
}

float ray_cast_light_depth(const Scene& scene, int x, int y) {
  const int n = scene.light.map_size;
  // The texel centre on the near plane, back through the inverse projection and view.
  const glm::vec4 ndc{(2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(n)) - 1.0f,
                      (2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(n)) - 1.0f, -1.0f, 1.0f};
  const glm::mat4 inverse = glm::inverse(scene.light_projection() * scene.light_view());
  glm::vec4 world = inverse * ndc;
  world /= world.w;
  // Ray with unit length along the light's axis (−y): parameter t = linear depth.
  const glm::dvec3 origin(scene.light_position);
  glm::dvec3 direction = glm::dvec3(world.x, world.y, world.z) - origin;
  direction /= -direction.y;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Box& b : scene.boxes) {  // slab test
    double t0 = 0.0, t1 = nearest;
    bool hit = true;
    for (int a = 0; a < 3 && hit; ++a) {
      const double lo = b.lo[a], hi = b.hi[a];
      if (std::fabs(direction[a]) < 1e-300) {
        hit = origin[a] >= lo && origin[a] <= hi;
        continue;
      }
      double ta = (lo - origin[a]) / direction[a], tb = (hi - origin[a]) / direction[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta), t1 = std::min(t1, tb);
      hit = t0 <= t1;
    }
    if (hit && t0 >= scene.light.near_plane && t0 <= scene.light.far_plane) nearest = std::min(nearest, t0);
  }
  return static_cast<float>(nearest);
}

}  // namespace pn
