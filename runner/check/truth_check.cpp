// Cases of the truth check (runner/truth, docs/truth.md), on the CPU only:
//   1. On each box scene, the Embree truth against the project's analytic
//      slab tests (scene.h, visibility_reference.h) on the very same rays:
//      the surface point and coverage against ray_cast_surface_point, whether
//      it faces the light against the hit box face's normal, and the visible
//      fraction against sees_point from the same surface point to the same
//      jittered light points. The two may disagree only on a tie: a segment
//      that grazes another box — passes within kGraze of its boundary — where
//      Embree's float ray, moved off the surface by the normal offset, and the
//      double slab test, moved kSelfOffset toward the light, may fall on
//      either side. Each differing segment must be such a graze; they are
//      counted, a pixel may differ by one sample at most, and on at most
//      kMaxTiedPixels pixels.
//   2. At light width 0, all S² samples are the light's centre: the truth is
//      one hard shadow, equal to one shadow ray per pixel (S = 1) exactly, and
//      to an independent slab-test ray per pixel except on grazes.
//   3. Its error against S = 64 falls as S grows (S = 1 … 32).
//   4. On the model scenes the slab tests cannot see (the spider on the ground,
//      the city with its poles and models: the frontier's), the truth against
//      a brute-force caster over every triangle in double
//      (scene/triangle_visibility_reference.h) on the very same rays: the
//      surface point, and each shadow segment from the same origin to the same
//      light point. Every segment where they disagree must graze a triangle
//      (pass within half the shadow offset of its boundary or plane), and at
//      most kMaxTiedModelPixels pixels may differ at all.
#include <cmath>
#include <optional>
#include <string>

#include "check/module_check.h"
#include "core/format.h"
#include "scene/city_scene.h"
#include "scene/model.h"
#include "scene/triangle_visibility_reference.h"
#include "scene/visibility_reference.h"
#include "truth/ray_traced_truth.h"

namespace pn {
namespace {

constexpr int kScreen = 64, kSamplesPerSide = 8;
constexpr int kConvergenceScreen = 48, kConvergenceReference = 64;
constexpr int kMaxTiedPixels = 4;  // of 4096; measured 0 on every scene (19 tied segments in 4.2M at 256², S = 8)
constexpr double kSurfaceAgreement = 1e-6;  // world units: both points lie on the same face plane in double
// World units: the normal offset (2e-4 on these scenes) moves a shadow ray by
// at most itself; Embree's float ray and kSelfOffset add ~1e-5.
constexpr double kGraze = 3e-4;
// The model scenes: a tie is a segment within half the shadow offset of a triangle (its own
// triangle's plane lies a whole offset from the segment's start, so it never counts as one).
constexpr double kTriangleGrazePerOffset = 0.5;
constexpr int kModelScreen = 48, kModelSamplesPerSide = 4;  // brute force: every triangle per segment
constexpr int kCityScreen = 32, kCitySamplesPerSide = 2;
constexpr int kMaxTiedModelPixels = 4;

TruthSettings check_settings(int samples_per_side, std::uint32_t seed = TruthSettings{}.seed) {
  TruthSettings s;
  s.samples_per_side = samples_per_side;
  s.seed = seed;
  s.progress = false;
  return s;
}

CaseResult scalar_case(const std::string& name, double target, double value, Tolerance tolerance) {
  const Image e(1, 1, 1, static_cast<float>(target)), o(1, 1, 1, static_cast<float>(value));
  return {name, tolerance, compare(e, o, tolerance)};
}

bool touches(const Box& b, const glm::dvec3& p) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < b.lo[a] - 1e-9 || p[a] > b.hi[a] + 1e-9) return false;
  return true;
}

// Whether the segment from `from` to `to` passes within `band` of the
// boundary of a box that `from` does not lie on: it meets the box grown by
// `band` but not the box shrunk by it.
bool grazes(const Scene& scene, const glm::dvec3& from, const glm::dvec3& to, double band) {
  for (const Box& b : scene.boxes) {
    if (touches(b, from)) continue;
    const glm::vec3 d(static_cast<float>(band));
    const Box grown{b.lo - d, b.hi + d}, shrunk{b.lo + d, b.hi - d};
    const bool inner = glm::all(glm::lessThan(shrunk.lo, shrunk.hi)) && box_entry(shrunk, from, to - from, 1.0);
    if (box_entry(grown, from, to - from, 1.0) && !inner) return true;
  }
  return false;
}

// The unit normal of the face of `b` that `p` lies on (the nearest face).
glm::dvec3 face_normal(const Box& b, const glm::dvec3& p) {
  glm::dvec3 normal(0.0);
  double nearest = INFINITY;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const double distance = std::fabs(p[a] - (side == 0 ? b.lo[a] : b.hi[a]));
      if (distance < nearest) nearest = distance, normal = glm::dvec3(0.0), normal[a] = side == 0 ? -1.0 : 1.0;
    }
  return normal;
}

std::string screen_name(const Scene& scene, int size, int samples_per_side) {
  return scene.name + " " + std::to_string(size) + "x" + std::to_string(size) + ", " +
         std::to_string(samples_per_side * samples_per_side) + " light samples";
}

// Whether pixel (x, y)'s truth surface `s` agrees with `expected`, the other caster's point (none:
// no surface): the same coverage, and within kSurfaceAgreement. A disagreement is a tie when the
// camera ray grazes (`grazes()`: counted in `grazing`), else its distance (+Inf: coverage) is the
// pixel's error.
template <class Grazes>
bool surfaces_agree(const TruthSurface& s, const std::optional<glm::dvec3>& expected, int x, int y,
                    const Grazes& grazes, Image& error, int& grazing) {
  const bool same_coverage = s.covered == expected.has_value();
  const double distance = same_coverage && s.covered ? glm::length(s.position - *expected) : 0.0;
  if (same_coverage && distance <= kSurfaceAgreement) return true;
  if (grazes())
    ++grazing;  // a tie: the two casters may meet different surfaces here
  else
    error.at(x, y) = same_coverage ? static_cast<float>(distance) : INFINITY;
  return false;
}

void slab_test_cases(const Scene& scene, std::vector<CaseResult>& out) {
  const TruthTracer tracer(scene, kScreen, check_settings(kSamplesPerSide));
  const int n = kScreen;
  Image surface_error(n, n), faces_expected(n, n), faces_observed(n, n), truth(n, n, 1, 1.0f), slab(n, n, 1, 1.0f),
      unexplained(n, n);
  int grazing_camera_rays = 0, tied_segments = 0, tied_pixels = 0, segments = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const TruthSurface s = tracer.surface(x, y);
      const auto expected = ray_cast_surface_point(scene, x, y, n);
      const auto camera_ray_grazes = [&] {
        const TruthTracer::Ray ray = tracer.camera_ray(x, y);
        return grazes(scene, ray.origin, ray.origin + ray.direction, kGraze);
      };
      if (!surfaces_agree(s, expected ? std::optional(expected->position) : std::nullopt, x, y, camera_ray_grazes,
                          surface_error, grazing_camera_rays) ||
          !s.covered)
        continue;
      const glm::dvec3 to_light = glm::dvec3(scene.light_position) - expected->position;
      faces_expected.at(x, y) = glm::dot(face_normal(scene.boxes[expected->box], expected->position), to_light) > 0;
      faces_observed.at(x, y) = s.faces_light;
      int seen_truth = 0, seen_slab = 0, tied = 0;
      for (const glm::dvec3& p : tracer.light_samples(x, y, s)) {
        const bool a = tracer.sees(s, p), b = sees_point(scene, s.position, p);
        seen_truth += a, seen_slab += b, ++segments;
        if (a == b) continue;
        ++tied;
        if (!grazes(scene, s.position, p, kGraze)) unexplained.at(x, y) += 1.0f;
      }
      const double count = kSamplesPerSide * kSamplesPerSide;
      truth.at(x, y) = static_cast<float>(seen_truth / count), slab.at(x, y) = static_cast<float>(seen_slab / count);
      tied_segments += tied, tied_pixels += tied > 0;
    }
  const std::string name = screen_name(scene, n, kSamplesPerSide);
  const Tolerance surface = Tolerance::absolute(kSurfaceAgreement);
  out.push_back({name + ": surface point (coverage, world distance) vs ray_cast_surface_point, " +
                     std::to_string(grazing_camera_rays) + " differing camera rays that graze a box left out",
                 surface, compare(Image(n, n), surface_error, surface)});
  out.push_back({name + ": faces the light vs the hit box face's normal", Tolerance::exact(),
                 compare(faces_expected, faces_observed, Tolerance::exact())});
  const Tolerance one_sample = Tolerance::absolute(1.0 / (kSamplesPerSide * kSamplesPerSide) + 1e-6);
  out.push_back({name + ": visible fraction vs slab tests on the same segments", one_sample,
                 compare(slab, truth, one_sample)});
  out.push_back({name + ": differing segments that graze no box within " + format_number("%g", kGraze) + " (" +
                     std::to_string(tied_segments) + " of " + std::to_string(segments) + " segments differ)",
                 Tolerance::exact(), compare(Image(n, n), unexplained, Tolerance::exact())});
  out.push_back(scalar_case(name + ": pixels whose fraction differs from the slab tests' (at most " +
                                std::to_string(kMaxTiedPixels) + ")",
                            0.0, tied_pixels, Tolerance::absolute(kMaxTiedPixels)));
}

void triangle_cases(const Scene& scene, int n, int samples_per_side, std::vector<CaseResult>& out) {
  const TruthTracer tracer(scene, n, check_settings(samples_per_side));
  const std::vector<glm::vec3> triangles = scene.triangles();
  const double band = kTriangleGrazePerOffset * tracer.offset();
  Image surface_error(n, n), truth(n, n, 1, 1.0f), brute(n, n, 1, 1.0f), unexplained(n, n);
  int grazing_camera_rays = 0, tied_segments = 0, tied_pixels = 0, segments = 0, shadowed = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const TruthSurface s = tracer.surface(x, y);
      const TruthTracer::Ray ray = tracer.camera_ray(x, y);
      const auto hit = nearest_triangle(triangles, ray.origin, ray.direction, 1.0);
      const auto camera_ray_grazes = [&] {
        return segment_grazes_triangles(triangles, ray.origin, ray.origin + ray.direction, band);
      };
      if (!surfaces_agree(s, hit ? std::optional(ray.origin + hit->t * ray.direction) : std::nullopt, x, y,
                          camera_ray_grazes, surface_error, grazing_camera_rays) ||
          !s.covered)
        continue;
      const glm::dvec3 origin = tracer.shadow_origin(s);
      int seen_truth = 0, seen_brute = 0, tied = 0;
      const std::vector<glm::dvec3> points = tracer.light_samples(x, y, s);
      for (const glm::dvec3& p : points) {
        const bool a = tracer.sees(s, p);
        const bool b = glm::dot(s.normal, p - s.position) > 0.0 && !segment_blocked(triangles, origin, p - origin, 1.0);
        seen_truth += a, seen_brute += b, ++segments;
        if (a == b) continue;
        ++tied;
        if (!segment_grazes_triangles(triangles, origin, p, band)) unexplained.at(x, y) += 1.0f;
      }
      const double count = static_cast<double>(points.size());
      truth.at(x, y) = static_cast<float>(seen_truth / count), brute.at(x, y) = static_cast<float>(seen_brute / count);
      tied_segments += tied, tied_pixels += tied > 0, shadowed += seen_brute < count;
    }
  const std::string name = screen_name(scene, n, samples_per_side) + ", " + std::to_string(triangles.size() / 3) +
                           " triangles, " + std::to_string(shadowed) + " pixels not fully lit";
  const Tolerance surface = Tolerance::absolute(kSurfaceAgreement);
  out.push_back({name + ": surface point (coverage, world distance) vs the nearest triangle in double, " +
                     std::to_string(grazing_camera_rays) + " differing camera rays that graze a triangle left out",
                 surface, compare(Image(n, n), surface_error, surface)});
  out.push_back({name + ": differing shadow segments that graze no triangle within " + format_number("%.2g", band) +
                     " (" + std::to_string(tied_segments) + " of " + std::to_string(segments) + " segments differ)",
                 Tolerance::exact(), compare(Image(n, n), unexplained, Tolerance::exact())});
  const Tolerance one_sample = Tolerance::absolute(1.0 / (samples_per_side * samples_per_side) + 1e-6);
  out.push_back({name + ": visible fraction vs the brute-force segments, within one sample", one_sample,
                 compare(brute, truth, one_sample)});
  out.push_back(scalar_case(name + ": pixels whose fraction differs from the brute force's (at most " +
                                std::to_string(kMaxTiedModelPixels) + ")",
                            0.0, tied_pixels, Tolerance::absolute(kMaxTiedModelPixels)));
}

void point_light_cases(Scene scene, std::vector<CaseResult>& out) {
  scene.light.width = 0.0;
  const int n = kScreen;
  const Truth many = trace_truth(scene, n, check_settings(kSamplesPerSide));
  const Truth one = trace_truth(scene, n, check_settings(1));
  Image independent(n, n, 1, 1.0f), observed = many.visibility;
  int grazing = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const auto surface = ray_cast_surface_point(scene, x, y, n);
      if (!surface) continue;
      const glm::dvec3 light(scene.light_position);
      independent.at(x, y) = sees_point(scene, surface->position, light) ? 1.0f : 0.0f;
      if (independent.at(x, y) != observed.at(x, y) && grazes(scene, surface->position, light, kGraze))
        observed.at(x, y) = independent.at(x, y), ++grazing;
    }
  const std::string name = scene.name + " " + std::to_string(n) + "x" + std::to_string(n) + ", light width 0";
  out.push_back({name + ": " + std::to_string(kSamplesPerSide * kSamplesPerSide) +
                     " light samples vs one shadow ray per pixel",
                 Tolerance::exact(), compare(one.visibility, many.visibility, Tolerance::exact())});
  out.push_back({name + ": vs one slab-test ray per pixel from ray_cast_surface_point, " + std::to_string(grazing) +
                     " grazing rays left out",
                 Tolerance::exact(), compare(independent, observed, Tolerance::exact())});
}

// Mean |expected - observed| over the penumbra: the pixels where `expected` is strictly between 0 and 1.
double mean_abs_error_in_penumbra(const Image& expected, const Image& observed) {
  double sum = 0.0;
  int count = 0;
  for (size_t i = 0; i < expected.texels.size(); ++i)
    if (expected.texels[i] > 0.0f && expected.texels[i] < 1.0f)
      sum += std::fabs(expected.texels[i] - observed.texels[i]), ++count;
  return count > 0 ? sum / count : 0.0;
}

void convergence_cases(const Scene& scene, std::vector<CaseResult>& out) {
  const int n = kConvergenceScreen;
  auto error_at = [&](int side, const Image& reference) {
    return mean_abs_error_in_penumbra(reference, trace_truth(scene, n, check_settings(side)).visibility);
  };
  // Another seed for the reference, so that its noise is independent of every run it scores.
  const Image reference =
      trace_truth(scene, n, check_settings(kConvergenceReference, TruthSettings{}.seed + 1)).visibility;
  double previous = error_at(1, reference);
  int previous_side = 1;
  for (int side : {2, 4, 8, 16, 32}) {
    const double error = error_at(side, reference);
    out.push_back(scalar_case(scene.name + " " + std::to_string(n) + "x" + std::to_string(n) + ", S = " +
                                  std::to_string(side) + ": mean |error| in the penumbra vs S = " +
                                  std::to_string(kConvergenceReference) + " " + format_number("%.5f", error) +
                                  ", below S = " + std::to_string(previous_side) + "'s " +
                                  format_number("%.5f", previous),
                              0.0, error, Tolerance::absolute(previous)));
    previous = error, previous_side = side;
  }
}

}  // namespace

std::vector<CaseResult> run_truth_check(const CheckEnvironment&) {
  std::vector<CaseResult> results;
  for (const auto& fixture : fixtures::kScenes) {
    const Scene scene = make_scene(fixture, 128);
    slab_test_cases(scene, results);
    point_light_cases(scene, results);
  }
  convergence_cases(make_scene(find_scene_fixture("boxes"), 128), results);
  triangle_cases(make_model_scene(fixtures::kCityModels[0], 128), kModelScreen, kModelSamplesPerSide, results);
  triangle_cases(make_city_scene(fixtures::kCityScenes[0], 128), kCityScreen, kCitySamplesPerSide, results);
  return results;
}

}  // namespace pn
