// The ray-traced truth (runner/truth) by hand on the table top floating under
// the light (hand_scene.h: the table is [-1, 1] x [9, 10] x [-1, 1], the
// light's centre at height 20). Seen from a ground point (x, 0, 0), a ray to
// the light point (xs, 20, zs) crosses the table's top plane y = 10 at
// x + (xs - x) / 2, so it is blocked iff xs <= 2 - x (for |zs| <= 2): the
// shadow edge of the light's centre is x = 2, and a light of width w has its
// penumbra on 2 - w/2 < x < 2 + w/2, where the fraction seen is that of the
// light's width with xs > 2 - x.
#include <catch2/catch.hpp>

#include <glm/glm.hpp>
#include <set>

#include "core/error.h"
#include "hand_scene.h"
#include "scene/scene.h"
#include "truth/embree_scene.h"
#include "truth/jittered_light_samples.h"
#include "truth/ray_traced_truth.h"

using pn::test::table_scene;

namespace {

pn::TruthSettings settings(int samples_per_side, std::uint32_t seed = pn::TruthSettings{}.seed, int threads = 0) {
  pn::TruthSettings s;
  s.samples_per_side = samples_per_side;
  s.seed = seed;
  s.threads = threads;
  s.progress = false;
  return s;
}

// A ground point at (x, 0, z) (normal +y) and pixel (3, 5)'s light samples.
struct GroundPoint {
  pn::TruthTracer tracer;
  pn::TruthSurface surface;
  std::vector<glm::dvec3> lights;
  GroundPoint(const pn::Scene& scene, int samples_per_side, double x, double z = 0.0)
      : tracer(scene, 16, settings(samples_per_side)),
        surface(tracer.surface_at({x, 0.0, z}, {0.0, 1.0, 0.0})),
        lights(tracer.light_samples(3, 5, surface)) {}
  double visibility() const { return tracer.visibility(surface, lights); }
  // By hand, for z = 0: the shadow ray starts at height e (the normal offset) and crosses the
  // table's top y = 10 at x + (xs - x)(10 - e)/(20 - e), blocked iff that is <= 1.
  double by_hand() const {
    const double x = surface.position.x, e = tracer.offset();
    int seen = 0;
    for (const glm::dvec3& p : lights) seen += x + (p.x - x) * (10.0 - e) / (20.0 - e) > 1.0;
    return static_cast<double>(seen) / static_cast<double>(lights.size());
  }
};

double ground_visibility(const pn::Scene& scene, int samples_per_side, double x, double z = 0.0) {
  return GroundPoint(scene, samples_per_side, x, z).visibility();
}

// The pixel of a size x size screen (from the lower left) whose centre is nearest `p`'s image.
glm::ivec2 pixel_of(const pn::Scene& scene, const glm::dvec3& p, int size) {
  const glm::dvec4 clip = glm::dmat4(scene.camera_projection() * scene.camera_view()) * glm::dvec4(p, 1.0);
  return {static_cast<int>((clip.x / clip.w * 0.5 + 0.5) * size), static_cast<int>((clip.y / clip.w * 0.5 + 0.5) * size)};
}

int differing_texels(const pn::Image& a, const pn::Image& b) {
  int count = 0;
  for (size_t i = 0; i < a.texels.size(); ++i) count += a.texels[i] != b.texels[i];
  return count;
}

}  // namespace

TEST_CASE("truth: the ground straight under the table's centre sees none of a 0.5-wide light", "[truth]") {
  CHECK(ground_visibility(table_scene(64, 0.5), 16, 0.0) == 0.0);
  CHECK(ground_visibility(table_scene(64, 0.5), 16, 1.7, 0.9) == 0.0);  // inside the umbra, x < 2 - w/2
}

TEST_CASE("truth: the ground far outside the penumbra (x = 8, and x = 2.3 > 2 + w/2) sees all of the light", "[truth]") {
  CHECK(ground_visibility(table_scene(64, 0.5), 16, 8.0) == 1.0);
  CHECK(ground_visibility(table_scene(64, 0.5), 16, 2.3) == 1.0);
}

TEST_CASE("truth: on the centre's shadow edge x = 2 the ground sees about half the light (by hand, with the offset)", "[truth]") {
  // The normal offset e lifts the ray: samples with -e/(10 - e) < xs <= 0, at most one column, see past the edge.
  for (double width : {0.01, 0.5})
    for (int side : {2, 3, 16}) {
      const GroundPoint edge(table_scene(64, width), side, 2.0);
      CHECK(edge.tracer.offset() == Approx(2e-4).epsilon(1e-9));  // 1e-5 of the 20-unit ground
      CHECK(edge.visibility() == edge.by_hand());
      const double even_half = side % 2 == 0 ? 0.5 : 0.5 - 0.5 / side;  // the columns wholly on the lit side
      CHECK(edge.visibility() >= even_half);
      CHECK(edge.visibility() <= even_half + 1.0 / side);
    }
}

TEST_CASE("truth: a quarter into the penumbra (x = 2 - w/4) the ground sees a quarter of the light for S = 4k", "[truth]") {
  for (int side : {4, 8, 16}) {
    const GroundPoint quarter(table_scene(64, 0.5), side, 2.0 - 0.5 / 4);
    CHECK(quarter.visibility() == quarter.by_hand());
    CHECK(quarter.visibility() == Approx(0.25).margin(1.0 / side));
  }
}

TEST_CASE("truth: the table's +z side, turned from the light's centre, does not face it and sees none of it", "[truth]") {
  const pn::Scene scene = table_scene(64, 0.5);
  const int n = 64;
  const glm::ivec2 side = pixel_of(scene, {0.0, 9.5, 1.0}, n);
  const pn::TruthTracer tracer(scene, n, settings(4));
  const pn::TruthSurface s = tracer.surface(side.x, side.y);
  REQUIRE(s.covered);
  CHECK(s.position.z == Approx(1.0).margin(1e-9));
  CHECK(s.normal.z == Approx(1.0).margin(1e-12));
  CHECK_FALSE(s.faces_light);
  const pn::Truth truth = pn::trace_truth(scene, n, settings(4));
  CHECK(truth.faces_light.at(side.x, side.y) == 0.0f);
  CHECK(truth.visibility.at(side.x, side.y) == 0.0f);
}

TEST_CASE("truth: a side face near its top edge sees none of a light just behind its plane, though no box is between", "[truth]") {
  // The box [-1, 1] x [0, 1] x [-1, 1]; the point (1, 0.999, 0) on its +x face; the light at x = 0.99.
  // A ray from the offset point (1 + 2e-4, 0.999, 0) would cross x = 1 only at y ~ 1.37, above the
  // box, and reach the light: only the rule that a sample behind the face's plane is dark for it holds.
  pn::Scene scene = table_scene(64, 0.001);
  scene.boxes = {scene.boxes[0], {{-1.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}}};
  scene.light_position = {0.99f, 20.0f, 0.0f};
  const pn::TruthTracer tracer(scene, 16, settings(4));
  const pn::TruthSurface face = tracer.surface_at({1.0, 0.999, 0.0}, {1.0, 0.0, 0.0});
  CHECK_FALSE(face.faces_light);
  CHECK(tracer.visibility(face, tracer.light_samples(0, 0, face)) == 0.0);
  // The same light just in front of the plane (x = 1.01) is seen whole.
  scene.light_position.x = 1.01f;
  const pn::TruthTracer front(scene, 16, settings(4));
  const pn::TruthSurface front_face = front.surface_at({1.0, 0.999, 0.0}, {1.0, 0.0, 0.0});
  CHECK(front.visibility(front_face, front.light_samples(0, 0, front_face)) == 1.0);
}

TEST_CASE("truth: a one-sided mesh quad wound to face down shadows like the table's top and faces the light from above", "[truth]") {
  pn::Scene scene = table_scene(64, 0.5);
  scene.boxes.resize(1);  // the ground only; the table's top becomes two triangles at y = 10, clockwise from above
  const glm::vec3 a{-1, 10, -1}, b{1, 10, -1}, c{1, 10, 1}, d{-1, 10, 1};
  scene.mesh = {a, b, c, a, c, d};
  CHECK(ground_visibility(scene, 16, 0.0) == 0.0);
  CHECK(ground_visibility(scene, 16, 2.3) == 1.0);
  const GroundPoint edge(scene, 16, 2.0);
  CHECK(edge.visibility() == edge.by_hand());
  const int n = 64;
  const glm::ivec2 top = pixel_of(scene, {0.0, 10.0, 0.0}, n);
  const pn::TruthTracer tracer(scene, n, settings(4));
  const pn::TruthSurface s = tracer.surface(top.x, top.y);
  REQUIRE(s.covered);
  CHECK(s.position.y == Approx(10.0).margin(1e-9));
  CHECK(s.normal.y == Approx(1.0).margin(1e-12));  // turned toward the camera, whatever the winding
  CHECK(s.faces_light);
  CHECK(tracer.visibility(s, tracer.light_samples(top.x, top.y, s)) == 1.0);
}

TEST_CASE("truth: pixels that see the sky are uncovered with visibility 1; the ground under the table is covered, 0", "[truth]") {
  const pn::Scene scene = table_scene(64, 0.5);
  const int n = 32;
  const pn::Truth truth = pn::trace_truth(scene, n, settings(4));
  // The top row looks past the ground's far edge, but for its middle pixels that see the table's +z side.
  int sky = 0;
  for (int x = 0; x < n; ++x) {
    CHECK(truth.covered.at(x, n - 1) == (x >= n / 2 - 2 && x < n / 2 + 2 ? 1.0f : 0.0f));
    if (truth.covered.at(x, n - 1) != 0.0f) continue;
    ++sky;
    CHECK(truth.visibility.at(x, n - 1) == 1.0f);
    CHECK(truth.faces_light.at(x, n - 1) == 0.0f);
  }
  CHECK(sky == n - 4);
  const glm::ivec2 under = pixel_of(scene, {0.0, 0.0, 0.0}, n);
  CHECK(truth.covered.at(under.x, under.y) == 1.0f);
  CHECK(truth.faces_light.at(under.x, under.y) == 1.0f);
  CHECK(truth.visibility.at(under.x, under.y) == 0.0f);
}

TEST_CASE("truth: a scene without geometry is uncovered everywhere with visibility 1", "[truth]") {
  pn::Scene scene = table_scene();
  scene.boxes.clear();
  const pn::Truth truth = pn::trace_truth(scene, 8, settings(2));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      CHECK(truth.covered.at(x, y) == 0.0f);
      CHECK(truth.visibility.at(x, y) == 1.0f);
    }
}

TEST_CASE("truth: the same seed gives the same images with 1 and 3 threads; another seed moves the penumbra's noise", "[truth]") {
  const pn::Scene scene = pn::make_scene(pn::find_scene_fixture("tall_blocker"), 64);
  const pn::Truth one = pn::trace_truth(scene, 32, settings(3, 7, 1));
  const pn::Truth three = pn::trace_truth(scene, 32, settings(3, 7, 3));
  CHECK(differing_texels(one.visibility, three.visibility) == 0);
  CHECK(differing_texels(one.covered, three.covered) == 0);
  CHECK(differing_texels(one.faces_light, three.faces_light) == 0);
  const pn::Truth other = pn::trace_truth(scene, 32, settings(3, 8, 1));
  CHECK(differing_texels(one.visibility, other.visibility) > 20);  // tall_blocker's penumbra spans many pixels
  CHECK(differing_texels(one.covered, other.covered) == 0);
}

TEST_CASE("jittered light samples: one point in each of the 5 x 5 cells of a width-2 light, jittered per pixel", "[truth]") {
  const pn::LightFrame light = pn::light_frame(table_scene(64, 2.0));
  const auto points = pn::jittered_light_samples(light, 5, 1, 10, 20);
  REQUIRE(points.size() == 25);
  std::set<std::pair<int, int>> cells;
  for (size_t k = 0; k < points.size(); ++k) {
    const glm::dvec3 p = points[k];
    CHECK(p.y == Approx(20.0).margin(1e-12));
    // The light view's x axis is world +x, its y axis world -z (scene.cpp's lookAt up vector).
    const int i = static_cast<int>((p.x + 1.0) / 2.0 * 5), j = static_cast<int>((1.0 - p.z) / 2.0 * 5);
    CHECK(i == static_cast<int>(k % 5));
    CHECK(j == static_cast<int>(k / 5));
    cells.insert({i, j});
  }
  CHECK(cells.size() == 25);
  CHECK(pn::jittered_light_samples(light, 5, 1, 10, 20) == points);
  CHECK(pn::jittered_light_samples(light, 5, 1, 11, 20) != points);
  CHECK(pn::jittered_light_samples(light, 5, 2, 10, 20) != points);
}

TEST_CASE("jittered light samples: a light of width 0 gives S x S copies of its centre", "[truth]") {
  for (const glm::dvec3& p : pn::jittered_light_samples(pn::light_frame(table_scene(64, 0.0)), 4, 9, 1, 2))
    CHECK(p == glm::dvec3(0.0, 20.0, 0.0));
}

TEST_CASE("embree scene: a ray meets a triangle at its hand-worked t and misses beside it; a segment short of it is free", "[truth]") {
  const pn::EmbreeScene triangle({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const auto hit = triangle.nearest({0.25, 0.25, 2.0}, {0.0, 0.0, -1.0}, 10.0);
  REQUIRE(hit);
  CHECK(hit->t == Approx(2.0).epsilon(1e-6));
  CHECK(hit->triangle == 0u);
  CHECK_FALSE(triangle.nearest({0.75, 0.75, 2.0}, {0.0, 0.0, -1.0}, 10.0));
  CHECK(triangle.blocked({0.25, 0.25, 2.0}, {0.0, 0.0, -1.0}, 3.0));
  CHECK_FALSE(triangle.blocked({0.25, 0.25, 2.0}, {0.0, 0.0, -1.0}, 1.5));
}

TEST_CASE("negative: truth inputs out of range are refused naming the setting and its range", "[truth]") {
  const pn::Scene scene = table_scene();
  CHECK_THROWS_WITH(pn::trace_truth(scene, 0, settings(4)), "truth screen size 0: expected 1..8192");
  CHECK_THROWS_WITH(pn::trace_truth(scene, 8193, settings(4)), "truth screen size 8193: expected 1..8192");
  CHECK_THROWS_WITH(pn::trace_truth(scene, 8, settings(0)), "truth samples per side 0: expected 1..64");
  CHECK_THROWS_WITH(pn::trace_truth(scene, 8, settings(65)), "truth samples per side 65: expected 1..64");
  CHECK_THROWS_WITH(pn::trace_truth(scene, 8, settings(4, 1, -1)),
                    "truth threads -1: expected 0..256 (0: one per hardware thread)");
  CHECK_THROWS_WITH(pn::TruthTracer(table_scene(64, -1.0), 8, settings(4)), "truth light width -1: expected a finite number >= 0");
  CHECK_THROWS_WITH(pn::EmbreeScene({{0, 0, 0}, {1, 0, 0}}),
                    "ray-traced truth: 2 triangle vertices: expected a multiple of 3");
}

TEST_CASE("truth under the sun: points in the cone of its disc, the table's shadow edge under its edge, penumbra S h wide", "[truth]") {
  // The sun straight down, 2 degrees wide, over the table [-1, 1] x [9, 10] x [-1, 1]: a ground
  // point (x, 0, 0) has every sun direction (dx, 1, dz) blocked while x + 9 tan(1 deg) < 1, and
  // none once x - 10 tan(1 deg) > 1: the penumbra reaches from 1 - 9 tan(1 deg) (the
  // underside's edge, umbra before it) to 1 + 10 tan(1 deg) (the top's edge, lit past it).
  pn::Scene scene = pn::test::table_scene(64, 0.0);
  const double theta = 2.0 * 3.14159265358979 / 180.0, tan_half = std::tan(0.5 * theta);
  pn::light_by_sun(scene, {0.0f, -1.0f, 0.0f}, theta);
  const pn::TruthTracer tracer(scene, 16, settings(16));
  REQUIRE(tracer.light().directional);
  const auto ground = [&](double x) { return tracer.surface_at({x, 0.0, 0.0}, {0.0, 1.0, 0.0}); };
  const pn::TruthSurface edge = ground(1.0);
  const std::vector<glm::dvec3> points = tracer.light_samples(3, 5, edge);
  REQUIRE(points.size() == 256);
  int blocked_by_hand = 0;
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = glm::normalize(p - edge.position);
    CHECK(d.y >= std::cos(0.5 * theta) - 1e-12);  // inside the sun's cone
    mean += d / 256.0;
    const glm::dvec3 origin = tracer.shadow_origin(edge);
    const double t = (9.0 - origin.y) / d.y;
    blocked_by_hand += std::fabs(origin.x + t * d.x) <= 1.0 && std::fabs(origin.z + t * d.z) <= 1.0;
  }
  CHECK(mean.x == Approx(0.0).margin(0.02 * tan_half));  // stratified: centred on the sun
  CHECK(mean.z == Approx(0.0).margin(0.02 * tan_half));
  CHECK(tracer.visibility(edge, points) == Approx(1.0 - blocked_by_hand / 256.0).margin(1e-12));
  CHECK(tracer.visibility(edge, points) == Approx(0.5).margin(0.03));
  for (const auto& [x, expected] : {std::pair{1.0 + 10 * tan_half + 0.01, 1.0}, {1.0 - 9 * tan_half - 0.01, 0.0}}) {
    const pn::TruthSurface s = ground(x);
    CHECK(tracer.visibility(s, tracer.light_samples(3, 5, s)) == expected);
  }
  CHECK(edge.faces_light);
  CHECK_FALSE(tracer.surface_at({0.0, 9.0, 0.0}, {0.0, -1.0, 0.0}).faces_light);  // the underside faces away
}
