// A triangle soup in Intel Embree 3, for the ray-traced truth: the nearest
// hit of a ray and whether a segment is blocked. Built once, robust
// (watertight: a ray cannot slip through the shared edge of two triangles, such
// as a box face's diagonal) and then only read, so any number of threads may
// trace at once. Owns its Embree device and scene (move-only, released in the
// destructor); Embree's errors become pn::Error.
// Rays are traced in float, as Embree does; callers keep their own geometry
// in double and refine (ray_traced_truth.cpp).
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

// Embree's handles, without its headers.
typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace pn {

class EmbreeScene {
 public:
  // `triangles`: three vertices a triangle (Scene::triangles()); throws Error
  // unless its size is a multiple of 3 and every coordinate is finite.
  explicit EmbreeScene(const std::vector<glm::vec3>& triangles);
  ~EmbreeScene();
  EmbreeScene(EmbreeScene&& other) noexcept;
  EmbreeScene& operator=(EmbreeScene&& other) noexcept;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  struct Hit {
    double t = 0;          // origin + t · direction is the hit
    unsigned triangle = 0;  // index into the triangle list (its vertices 3·triangle … 3·triangle + 2)
  };
  // The nearest triangle that origin + t · direction meets, t in [0, t_max].
  std::optional<Hit> nearest(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) const;
  // Whether any triangle meets origin + t · direction for t in [0, t_max].
  bool blocked(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) const;

 private:
  void release() noexcept;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace pn
