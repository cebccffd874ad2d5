#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/format.h"
#include "core/named.h"
#include "core/seeded_random.h"
#include "scene/light_view.h"

namespace pn {

double SunLight::spread() const { return 2.0 * std::tan(0.5 * angular_diameter_radians); }

glm::mat4 Scene::light_view() const {
  if (sun) return sun->view;
  return glm::lookAt(light_position, light_position + glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
}

glm::mat4 Scene::light_projection() const {
  if (sun) return sun->projection;
  return glm::perspective(static_cast<float>(light.fov_radians), 1.0f, static_cast<float>(light.near_plane),
                          static_cast<float>(light.far_plane));
}

glm::mat4 SceneCamera::view() const { return glm::lookAt(eye, target, glm::vec3(0, 1, 0)); }

glm::mat4 Scene::camera_view() const { return camera.view(); }

glm::mat4 Scene::camera_projection() const {
  return glm::perspective(glm::radians(camera.fov_degrees), 1.0f, camera.near_plane, camera.far_plane);
}

std::pair<glm::vec3, glm::vec3> Scene::bounds() const {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const Box& b : boxes) lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi);
  for (const glm::vec3& v : mesh) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return {lo, hi};
}

Scene with_shadow_map_size(Scene scene, int shadow_map_size) {
  scene.light.map_size = shadow_map_size;
  if (scene.sun) light_by_sun(scene, scene.sun->direction, scene.sun->angular_diameter_radians);  // its texel width
  scene.light.validate();
  return scene;
}

void light_by_sun(Scene& scene, const glm::vec3& direction, double angular_diameter_radians) {
  const double max_diameter = 10.0 * 3.14159265358979 / 180.0;
  if (!(angular_diameter_radians > 0 && angular_diameter_radians < max_diameter))
    throw Error("sun angular diameter " + format_number("%g", angular_diameter_radians * 180.0 / 3.14159265358979) +
                " degrees: expected 0 < diameter < 10");
  const auto [lo, hi] = scene.bounds();
  SunLight sun;
  sun.direction = direction;
  sun.angular_diameter_radians = angular_diameter_radians;
  sun.view = directional_light_view(direction, lo, hi);  // throws for a zero or non-finite direction
  // The light-space box of the scene's eight corners: a square map over it, depths from its near face.
  glm::dvec3 box_lo(INFINITY), box_hi(-INFINITY);
  for (const glm::dvec3& corner : box_corners(lo, hi)) {
    const glm::dvec3 p(glm::dmat4(sun.view) * glm::dvec4(corner, 1.0));
    box_lo = glm::min(box_lo, p), box_hi = glm::max(box_hi, p);
  }
  const double half = 0.5 * std::max(box_hi.x - box_lo.x, box_hi.y - box_lo.y);
  const glm::dvec2 centre = 0.5 * (glm::dvec2(box_lo) + glm::dvec2(box_hi));
  const double near = -box_hi.z, far = -box_lo.z;  // the view looks down -z
  sun.projection = glm::mat4(glm::ortho(centre.x - half, centre.x + half, centre.y - half, centre.y + half, near, far));
  scene.light.width = 0.0;
  scene.light.spread = sun.spread();
  scene.light.near_plane = near;
  scene.light.far_plane = far;
  scene.light.texel_world = 2.0 * half / scene.light.map_size;
  scene.light.validate();
  scene.sun = sun;
}

std::vector<glm::vec3> Scene::triangles() const {
  std::vector<glm::vec3> out;
  out.reserve(36 * boxes.size() + mesh.size());
  for (const Box& b : boxes) {
    const glm::vec3 c[8] = {{b.lo.x, b.lo.y, b.lo.z}, {b.hi.x, b.lo.y, b.lo.z}, {b.hi.x, b.hi.y, b.lo.z},
                            {b.lo.x, b.hi.y, b.lo.z}, {b.lo.x, b.lo.y, b.hi.z}, {b.hi.x, b.lo.y, b.hi.z},
                            {b.hi.x, b.hi.y, b.hi.z}, {b.lo.x, b.hi.y, b.hi.z}};
    // Two triangles per face, counter-clockwise seen from outside.
    static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (const auto& f : faces)
      for (int i : {0, 1, 2, 0, 2, 3}) out.push_back(c[f[i]]);
  }
  out.insert(out.end(), mesh.begin(), mesh.end());
  return out;
}

const fixtures::SceneFixture& find_scene_fixture(const std::string& name) {
  return find_named(fixtures::kScenes, name, "unknown scene '" + name + "'");
}

void validate_light_width_factor(double factor, const char* what) {
  // At least float's smallest normal number (issue 39 C22): below it the light width is a
  // subnormal or 0 in the truth's float rays.
  if (!std::isfinite(factor) || factor <= 0)
    throw Error(std::string(what) + " " + format_shortest(factor) + ": expected a finite number > 0");
  if (factor < std::numeric_limits<float>::min())
    throw Error(std::string(what) + " " + format_shortest(factor) + ": expected a finite number > 0 that float holds "
                "(1.2e-38 or more)");
}

void scale_light_width(Scene& scene, double factor, const char* what) {
  validate_light_width_factor(factor, what);
  if (scene.sun) {  // the sun's angular diameter, its whole-scene map fitted again
    light_by_sun(scene, scene.sun->direction, scene.sun->angular_diameter_radians * factor);
    return;
  }
  const double base = scene.light.width;
  scene.light.width *= factor;
  if (!(scene.light.width <= kMaxLightWidth))
    throw Error(std::string(what) + " " + format_number("%g", factor) + ": the light would be " +
                format_number("%g", scene.light.width) + " wide, past the " + format_number("%g", kMaxLightWidth) +
                " the ray-traced truth's float rays represent: expected a factor <= " +
                format_number("%g", kMaxLightWidth / base));
  scene.light.validate();
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
      scene.boxes.push_back({{-1.0f, 0.0f, -1.0f}, {1.0f, 10.0f, 1.0f}});
      break;
  }
  return scene;
}

std::optional<std::pair<double, double>> box_span(const Box& b, const glm::dvec3& origin, const glm::dvec3& direction,
                                                  double t_min, double t_max) {
  double t0 = t_min, t1 = t_max;
  for (int a = 0; a < 3; ++a) {  // slab method
    const double lo = b.lo[a], hi = b.hi[a];
    if (std::fabs(direction[a]) < 1e-300) {
      if (origin[a] < lo || origin[a] > hi) return std::nullopt;
      continue;
    }
    double ta = (lo - origin[a]) / direction[a], tb = (hi - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    if (t0 > t1) return std::nullopt;
  }
  return std::pair{t0, t1};
}

std::optional<double> box_entry(const Box& b, const glm::dvec3& origin, const glm::dvec3& direction, double t_max) {
  const auto span = box_span(b, origin, direction, 0.0, t_max);
  if (!span) return std::nullopt;
  return span->first;
}

namespace {

// Nearest box hit along origin + t·direction with t in [t_min, t_max]; +Inf when none.
double nearest_hit(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Box& b : scene.boxes)
    if (const auto t = box_entry(b, origin, direction, std::min(nearest, t_max)); t && *t >= t_min) nearest = *t;
  return nearest;
}

// The point on the near plane of view·projection through pixel centre (x, y) of a size×size target.
glm::dvec3 through_pixel(const glm::mat4& view_projection, int x, int y, int size) {
  const glm::vec4 ndc{(2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(size)) - 1.0f,
                      (2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(size)) - 1.0f, -1.0f, 1.0f};
  glm::vec4 world = glm::inverse(view_projection) * ndc;
  return glm::dvec3(world) / static_cast<double>(world.w);
}

}  // namespace

namespace {
// The ray from the light through texel (x, y)'s centre, of unit length along the light's axis
// (−y): its parameter is the linear depth.
std::pair<glm::dvec3, glm::dvec3> light_ray(const Scene& scene, int x, int y) {
  const glm::dvec3 origin(scene.light_position);
  const glm::dvec3 on_near = through_pixel(scene.light_projection() * scene.light_view(), x, y, scene.light.map_size);
  glm::dvec3 direction = on_near - origin;
  direction /= -direction.y;
  return {origin, direction};
}
}  // namespace

float ray_cast_light_depth(const Scene& scene, int x, int y) {
  const auto [origin, direction] = light_ray(scene, x, y);
  return static_cast<float>(nearest_hit(scene, origin, direction, scene.light.near_plane, scene.light.far_plane));
}

float ray_cast_second_layer(const Scene& scene, int x, int y, bool back_faces, double margin) {
  const auto [origin, direction] = light_ray(scene, x, y);
  const double first = nearest_hit(scene, origin, direction, scene.light.near_plane, scene.light.far_plane);
  double nearest = std::numeric_limits<double>::infinity();
  for (const Box& b : scene.boxes) {
    // The ray's whole line through the box: entry t0, exit t1.
    const auto span = box_span(b, origin, direction, -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity());
    if (!span) continue;
    const auto [t0, t1] = *span;
    // Its faces the ray crosses inside the light's depth range: the exit faces away from the light.
    for (const double t : {t0, t1}) {
      if (t < scene.light.near_plane || t > scene.light.far_plane) continue;
      if (back_faces ? t == t1 : t > first + margin * std::fabs(first)) nearest = std::min(nearest, t);
    }
  }
  return static_cast<float>(nearest);
}

CameraRay camera_ray(const glm::dmat4& inverse_view_projection, int x, int y, int size) {
  const double nx = 2.0 * (x + 0.5) / size - 1.0, ny = 2.0 * (y + 0.5) / size - 1.0;
  const glm::dvec4 near4 = inverse_view_projection * glm::dvec4(nx, ny, -1.0, 1.0);
  const glm::dvec4 far4 = inverse_view_projection * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 origin = glm::dvec3(near4) / near4.w;
  return {origin, glm::dvec3(far4) / far4.w - origin};
}

std::optional<SurfacePoint> ray_cast_surface_point(const Scene& scene, int x, int y, int size) {
  const auto [origin, direction] =
      camera_ray(glm::inverse(glm::dmat4(scene.camera_projection() * scene.camera_view())), x, y, size);
  std::optional<SurfacePoint> nearest;
  double nearest_t = INFINITY;
  for (size_t b = 0; b < scene.boxes.size(); ++b)
    if (const auto t = box_entry(scene.boxes[b], origin, direction, 1.0); t && *t < nearest_t)
      nearest_t = *t, nearest = SurfacePoint{origin + *t * direction, static_cast<int>(b)};
  return nearest;
}

Receiver project_to_light(const Scene& scene, const glm::dvec3& point) {
  const glm::dvec4 view = glm::dmat4(scene.light_view()) * glm::dvec4(point, 1.0);
  const glm::dvec4 clip = glm::dmat4(scene.light_projection()) * view;
  Receiver r;
  r.valid = clip.w > 0.0;
  r.u = (clip.x / clip.w * 0.5 + 0.5) * scene.light.map_size;
  r.v = (clip.y / clip.w * 0.5 + 0.5) * scene.light.map_size;
  r.depth = -view.z;
  return r;
}

Receiver ray_cast_receiver(const Scene& scene, int x, int y, int size) {
  const auto surface = ray_cast_surface_point(scene, x, y, size);
  return surface ? project_to_light(scene, surface->position) : Receiver{};
}

bool receiver_on_surface_near_pixel(const Scene& scene, double u, double v, double depth, int x, int y, int size,
                                    double tolerance) {
  // Back from the shadow map: NDC, light view space (x_ndc = P00 x_view / depth), world.
  const glm::dmat4 projection(scene.light_projection());
  const double nx = u / scene.light.map_size * 2.0 - 1.0, ny = v / scene.light.map_size * 2.0 - 1.0;
  const glm::dvec4 view(nx * depth / projection[0][0], ny * depth / projection[1][1], -depth, 1.0);
  const glm::dvec3 p = glm::dvec3(glm::inverse(glm::dmat4(scene.light_view())) * view);
  bool on_surface = false;
  for (const Box& b : scene.boxes) {
    bool inside = true;
    double nearest_face = INFINITY;
    for (int a = 0; a < 3; ++a) {
      inside = inside && p[a] >= b.lo[a] - tolerance && p[a] <= b.hi[a] + tolerance;
      nearest_face = std::min({nearest_face, std::fabs(p[a] - b.lo[a]), std::fabs(p[a] - b.hi[a])});
    }
    on_surface = on_surface || (inside && nearest_face <= tolerance);
  }
  const glm::dvec4 clip = glm::dmat4(scene.camera_projection() * scene.camera_view()) * glm::dvec4(p, 1.0);
  const double px = (clip.x / clip.w * 0.5 + 0.5) * size, py = (clip.y / clip.w * 0.5 + 0.5) * size;
  return on_surface && std::fabs(px - (x + 0.5)) <= 1.0 && std::fabs(py - (y + 0.5)) <= 1.0;
}

}  // namespace pn
