// The truth every technique is scored against (SPEC §4.9): area-light
// visibility ray-traced with Embree on the CPU. Per screen pixel, the surface
// point the G-buffer's camera sees through the pixel's centre (over
// Scene::triangles(), so meshes count as well as boxes), and the fraction of
// S x S stratified, jittered points on the square light (truth/
// jittered_light_samples.h) that it sees: shadow rays from the point moved a
// small offset along its geometric normal (no shadow map, so no acne).
// docs/truth.md: sampling, offset, cost, limits, checks.
// Cost: per pixel one camera ray and S² shadow rays, over `threads` threads.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "core/image.h"
#include "scene/scene.h"
#include "truth/embree_scene.h"
#include "truth/jittered_light_samples.h"

namespace pn {

inline constexpr int kMaxTruthScreen = 8192;
inline constexpr int kMaxTruthSamplesPerSide = 64;
inline constexpr int kMaxTruthThreads = 256;
// The shadow rays' offset along the normal, as a fraction of the scene's
// extent (largest side of its triangles' bounding box): 2e-4 world units on
// the 20-unit fixture scenes, some 100 float ulps of their coordinates, and
// far below any of their features (the fence's posts are 0.12 wide).
inline constexpr double kShadowOffsetPerExtent = 1e-5;

struct TruthSettings {
  int samples_per_side = 16;  // S: S² light samples per pixel
  std::uint32_t seed = 0x5eed7247u;
  int threads = 0;  // 0: std::thread::hardware_concurrency()
  bool progress = true;  // a progress line on stderr when a trace takes more than a second
};

// Throws Error naming the setting and its range: screen size 1..8192,
// samples per side 1..64, threads 0..256.
void validate_truth_inputs(int screen_size, const TruthSettings& settings);

// Per pixel of a screen_size² screen, rows from the bottom (as GL reads textures back).
struct Truth {
  Image visibility;   // fraction of light samples seen, k / S²; 1 where the pixel sees no surface
  Image covered;      // 1: the pixel sees a surface, 0: none
  Image faces_light;  // 1: covered and N·L > 0 (N the geometric normal facing the camera, L toward the light's centre)
};
Truth trace_truth(const Scene& scene, int screen_size, const TruthSettings& settings);

// What a pixel's camera ray meets.
struct TruthSurface {
  bool covered = false;
  glm::dvec3 position{0.0};  // on the hit triangle's plane, in double
  glm::dvec3 normal{0.0};    // unit geometric normal, on the camera's side of the triangle
  bool faces_light = false;  // normal · (light centre − position) > 0
};

// The pieces of trace_truth, for checks and tests that test the same rays
// another way. Holds the Embree scene of `scene.triangles()`; read-only
// after construction, so threads may share it.
class TruthTracer {
 public:
  // Validates (validate_truth_inputs) and builds the Embree scene.
  TruthTracer(const Scene& scene, int screen_size, const TruthSettings& settings);

  // The ray from the camera's near plane through the centre of pixel (x, y)
  // (from the lower left) to its far plane, t in [0, 1]: the convention of ray_cast_surface_point.
  using Ray = CameraRay;
  Ray camera_ray(int x, int y) const;  // scene.h's camera_ray on this screen
  TruthSurface surface(int x, int y) const;
  // A surface point's surface as the truth sees it (position, normal), e.g. one worked by hand.
  TruthSurface surface_at(const glm::dvec3& position, const glm::dvec3& camera_side_normal) const;

  // The S² jittered light points of pixel (x, y) whose surface is `surface` (the sun's points
  // lie along directions from it; an area light's do not depend on it).
  std::vector<glm::dvec3> light_samples(int x, int y, const TruthSurface& surface) const;
  // Where a surface's shadow rays start: position + offset() · normal.
  glm::dvec3 shadow_origin(const TruthSurface& surface) const;
  double offset() const { return offset_; }
  // Whether `surface` sees `light_point`: the point lies in front of the
  // surface's plane (behind it, the surface itself is in the way: a face
  // turned from a sample is dark for it even when its mesh is open) and the
  // shadow ray from shadow_origin to it is blocked by no triangle.
  bool sees(const TruthSurface& surface, const glm::dvec3& light_point) const;
  // Fraction of `light_points` the surface sees; 1 for an uncovered pixel.
  double visibility(const TruthSurface& surface, const std::vector<glm::dvec3>& light_points) const;

  const LightFrame& light() const { return light_; }
  const TruthSettings& settings() const { return settings_; }

 private:
  std::vector<glm::vec3> triangles_;
  EmbreeScene rays_;
  LightFrame light_;
  TruthSettings settings_;
  int screen_size_;
  glm::dmat4 camera_inverse_;  // inverse of camera_projection() · camera_view()
  double offset_ = 0;
};

}  // namespace pn
