#include "truth/ray_traced_truth.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include "core/error.h"
#include "core/format.h"
#include "truth/progress_line.h"

namespace pn {
namespace {

void require_in_range(const char* setting, long long value, long long lo, long long hi, const char* note = "") {
  if (value < lo || value > hi)
    throw Error(std::string("truth ") + setting + " " + std::to_string(value) + ": expected " + std::to_string(lo) +
                ".." + std::to_string(hi) + note);
}

// Largest side of the triangles' bounding box (0 for none).
double extent_of(const std::vector<glm::vec3>& triangles) {
  if (triangles.empty()) return 0.0;
  glm::dvec3 lo(triangles[0]), hi(triangles[0]);
  for (const glm::vec3& v : triangles) lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
  const glm::dvec3 side = hi - lo;
  return std::max({side.x, side.y, side.z});
}

// The scene's triangles, once the inputs are known to be valid.
std::vector<glm::vec3> validated_triangles(const Scene& scene, int screen_size, const TruthSettings& settings) {
  validate_truth_inputs(screen_size, settings);
  const double width = scene.light.width;
  if (!std::isfinite(width) || width < 0.0)
    throw Error("truth light width " + format_number("%g", width) + ": expected a finite number >= 0");
  if (scene.sun && !(scene.sun->angular_diameter_radians >= 0.0 && scene.sun->angular_diameter_radians < 3.0))
    throw Error("truth sun angular diameter " + format_number("%g", scene.sun->angular_diameter_radians) +
                ": expected 0 <= diameter < 3 radians");
  return scene.triangles();
}

int thread_count(const TruthSettings& settings, int rows) {
  const int wanted = settings.threads > 0 ? settings.threads
                                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(wanted, 1, rows);
}

}  // namespace

void validate_truth_inputs(int screen_size, const TruthSettings& settings) {
  require_in_range("screen size", screen_size, 1, kMaxTruthScreen);
  require_in_range("samples per side", settings.samples_per_side, 1, kMaxTruthSamplesPerSide);
  require_in_range("threads", settings.threads, 0, kMaxTruthThreads, " (0: one per hardware thread)");
}

TruthTracer::TruthTracer(const Scene& scene, int screen_size, const TruthSettings& settings)
    : triangles_(validated_triangles(scene, screen_size, settings)),
      rays_(triangles_),
      light_(light_frame(scene)),
      settings_(settings),
      screen_size_(screen_size),
      camera_inverse_(glm::inverse(glm::dmat4(scene.camera_projection() * scene.camera_view()))),
      offset_(kShadowOffsetPerExtent * extent_of(triangles_)) {}

TruthTracer::Ray TruthTracer::camera_ray(int x, int y) const {
  return pn::camera_ray(camera_inverse_, x, y, screen_size_);  // the same ray as ray_cast_surface_point's
}

TruthSurface TruthTracer::surface(int x, int y) const {
  const Ray ray = camera_ray(x, y);
  const auto hit = rays_.nearest(ray.origin, ray.direction, 1.0);
  if (!hit) return {};
  const glm::dvec3 v0(triangles_[3 * hit->triangle]), v1(triangles_[3 * hit->triangle + 1]),
      v2(triangles_[3 * hit->triangle + 2]);
  glm::dvec3 normal = glm::cross(v1 - v0, v2 - v0);
  const double area = glm::length(normal);
  normal = area > 0.0 ? normal / area : -glm::normalize(ray.direction);
  // Embree's t is float; the hit's own plane, in double, puts the point on the surface (to ~1e-12 rather
  // than ~1e-5 world units), so the offset only has to clear the shadow rays' float rounding.
  double t = hit->t;
  const double along = glm::dot(normal, ray.direction);
  if (std::fabs(along) > 1e-9 * glm::length(ray.direction)) {
    const double on_plane = glm::dot(normal, v0 - ray.origin) / along;
    if (std::fabs(on_plane - t) <= 1e-4) t = on_plane;
  }
  return surface_at(ray.origin + t * ray.direction, along > 0.0 ? -normal : normal);
}

TruthSurface TruthTracer::surface_at(const glm::dvec3& position, const glm::dvec3& camera_side_normal) const {
  TruthSurface s;
  s.covered = true;
  s.position = position;
  s.normal = glm::normalize(camera_side_normal);
  s.faces_light = faces_light(light_, position, s.normal);
  return s;
}

std::vector<glm::dvec3> TruthTracer::light_samples(int x, int y, const TruthSurface& surface) const {
  if (light_.directional)
    return jittered_sun_points(light_, settings_.samples_per_side, settings_.seed, x, y, surface.position);
  return jittered_light_samples(light_, settings_.samples_per_side, settings_.seed, x, y);
}

glm::dvec3 TruthTracer::shadow_origin(const TruthSurface& surface) const {
  return surface.position + offset_ * surface.normal;
}

bool TruthTracer::sees(const TruthSurface& surface, const glm::dvec3& light_point) const {
  if (glm::dot(surface.normal, light_point - surface.position) <= 0.0) return false;
  const glm::dvec3 origin = shadow_origin(surface);
  return !rays_.blocked(origin, light_point - origin, 1.0);
}

double TruthTracer::visibility(const TruthSurface& surface, const std::vector<glm::dvec3>& light_points) const {
  if (!surface.covered || light_points.empty()) return 1.0;
  int seen = 0;
  for (const glm::dvec3& p : light_points) seen += sees(surface, p) ? 1 : 0;
  return static_cast<double>(seen) / static_cast<double>(light_points.size());
}

Truth trace_truth(const Scene& scene, int screen_size, const TruthSettings& settings) {
  const TruthTracer tracer(scene, screen_size, settings);
  const int n = screen_size;
  Truth truth{Image(n, n, 1, 1.0f), Image(n, n, 1, 0.0f), Image(n, n, 1, 0.0f)};
  auto trace_row = [&](int y) {  // a row is written by one thread only
    for (int x = 0; x < n; ++x) {
      const TruthSurface s = tracer.surface(x, y);
      if (!s.covered) continue;
      truth.covered.at(x, y) = 1.0f;
      truth.faces_light.at(x, y) = s.faces_light ? 1.0f : 0.0f;
      truth.visibility.at(x, y) = static_cast<float>(tracer.visibility(s, tracer.light_samples(x, y, s)));
    }
  };
  const int samples = settings.samples_per_side * settings.samples_per_side;
  ProgressLine progress("truth: " + std::to_string(n) + "x" + std::to_string(n) + ", " + std::to_string(samples) +
                            " light samples",
                        settings.progress);
  std::atomic<int> next_row{0}, rows_done{0};
  std::mutex failure_mutex;
  std::exception_ptr failure;
  // Every thread takes the next untraced row until none is left; the calling thread also reports progress.
  auto trace_rows = [&](bool report) {
    try {
      for (int y = next_row++; y < n; y = next_row++) {
        trace_row(y);
        const int done = ++rows_done;
        if (report) progress.update(static_cast<double>(done) / n);
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next_row = n;  // the others stop after their current row
    }
  };
  {
    std::vector<std::jthread> helpers;  // joined when this block ends, also when starting one throws
    try {
      for (int k = 1; k < thread_count(settings, n); ++k) helpers.emplace_back(trace_rows, false);
    } catch (...) {
      next_row = n;
      throw;
    }
    trace_rows(true);
  }
  if (failure) std::rethrow_exception(failure);
  progress.update(1.0);
  return truth;
}

}  // namespace pn
