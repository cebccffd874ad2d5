#include "scene/visibility_reference.h"

#include <algorithm>
#include <cmath>

#include "scene/light_samples.h"

namespace pn {
namespace {

// Where origin + t·direction, t in [0, 1], enters box b (slab method); none if it misses.
std::optional<double> segment_entry(const Box& b, const glm::dvec3& origin, const glm::dvec3& direction) {
  double t0 = 0.0, t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double lo = b.lo[a], hi = b.hi[a];
    if (direction[a] == 0.0) {
      if (origin[a] < lo || origin[a] > hi) return std::nullopt;
      continue;
    }
    double ta = (lo - origin[a]) / direction[a], tb = (hi - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    if (t0 > t1) return std::nullopt;
  }
  return t0;
}

}  // namespace

std::optional<SurfacePoint> ray_cast_surface_point(const Scene& scene, int x, int y, int size) {
  // Built here from the camera's matrices alone (near plane to far plane), so that this definition owes
  // nothing to the G-buffer's caster or to the light.
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(scene.camera_projection() * scene.camera_view()));
  const double nx = 2.0 * (x + 0.5) / size - 1.0, ny = 2.0 * (y + 0.5) / size - 1.0;
  const glm::dvec4 near4 = inverse * glm::dvec4(nx, ny, -1.0, 1.0), far4 = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 origin = glm::dvec3(near4) / near4.w, direction = glm::dvec3(far4) / far4.w - origin;
  std::optional<SurfacePoint> nearest;
  double nearest_t = INFINITY;
  for (size_t b = 0; b < scene.boxes.size(); ++b)
    if (const auto t = segment_entry(scene.boxes[b], origin, direction); t && *t < nearest_t)
      nearest_t = *t, nearest = SurfacePoint{origin + *t * direction, static_cast<int>(b)};
  return nearest;
}

bool sees_point(const Scene& scene, const glm::dvec3& point, const glm::dvec3& light) {
  const glm::dvec3 to_light = light - point;
  const double length = glm::length(to_light);
  if (length <= kSelfOffset) return true;
  const glm::dvec3 start = point + to_light * (kSelfOffset / length);
  return std::none_of(scene.boxes.begin(), scene.boxes.end(),
                      [&](const Box& b) { return segment_entry(b, start, light - start).has_value(); });
}

double visible_fraction(const Scene& scene, const glm::dvec3& point, const std::vector<glm::vec3>& lights) {
  if (lights.empty()) return 1.0;
  int seen = 0;
  for (const glm::vec3& light : lights) seen += sees_point(scene, point, glm::dvec3(light)) ? 1 : 0;
  return static_cast<double>(seen) / static_cast<double>(lights.size());
}

ShadowMapAnswers shadow_map_answers(const Scene& scene, const glm::dvec3& point, double bias) {
  const glm::dvec4 view = glm::dmat4(scene.light_view()) * glm::dvec4(point, 1.0);
  const glm::dvec4 clip = glm::dmat4(scene.light_projection()) * view;
  ShadowMapAnswers answers;
  if (!(clip.w > 0.0)) {
    answers.lit = true;
    return answers;
  }
  const double n = scene.light.map_size, depth = -view.z;
  const double u = (clip.x / clip.w * 0.5 + 0.5) * n, v = (clip.y / clip.w * 0.5 + 0.5) * n;
  for (double du : {-kTexelTie, kTexelTie})
    for (double dv : {-kTexelTie, kTexelTie}) {
      const double tu = std::floor(u + du), tv = std::floor(v + dv);
      const bool inside = tu >= 0 && tv >= 0 && tu < n && tv < n;
      if (inside && ray_cast_light_depth(scene, static_cast<int>(tu), static_cast<int>(tv)) < depth - bias)
        answers.shadowed = true;
      else
        answers.lit = true;
    }
  return answers;
}

VisibilityReference visibility_reference(const Scene& scene, int size, int samples_per_side, double bias) {
  const std::vector<glm::vec3> lights = light_sample_points(scene, samples_per_side);
  std::vector<Scene> moved(lights.size(), scene);  // one point light per sample, for its shadow map
  for (size_t k = 0; k < lights.size(); ++k) moved[k].light_position = lights[k];
  VisibilityReference out{Image(size, size, 1, 1.0f), Image(size, size, 1, 1.0f), Image(size, size, 1, 1.0f),
                          Image(size, size, 1, -1.0f)};
  const double count = static_cast<double>(lights.size());
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto surface = ray_cast_surface_point(scene, x, y, size);
      if (!surface) continue;
      int seen = 0, lowest = 0, highest = 0;
      for (size_t k = 0; k < lights.size(); ++k) {
        const bool exact = sees_point(scene, surface->position, glm::dvec3(lights[k]));
        const ShadowMapAnswers raster = shadow_map_answers(moved[k], surface->position, bias);
        seen += exact;
        lowest += exact && !raster.shadowed;
        highest += exact || raster.lit;
      }
      out.fraction.at(x, y) = static_cast<float>(seen / count);
      out.lowest.at(x, y) = static_cast<float>(lowest / count);
      out.highest.at(x, y) = static_cast<float>(highest / count);
      out.box.at(x, y) = static_cast<float>(surface->box);
    }
  return out;
}

}  // namespace pn
