// The surface pass on a real GL context: its albedo and cosine to the
// light's centre equal a CPU ray cast's off face edges.
#include <catch2/catch.hpp>

#include <cmath>

#include "check/compare.h"
#include "gl/texture.h"
#include "hand_scene.h"
#include "pass_runners/surface_pass.h"
#include "scene/scene.h"
#include "gl_test_context.h"

using pn::test::gl_context;


namespace {

// The face a ray-cast point lies on: box * 6 + axis * 2 + (1 on the high side), and its outward normal.
int face_of(const pn::Scene& scene, const pn::SurfacePoint& s, glm::dvec3& normal) {
  const pn::Box& b = scene.boxes[s.box];
  int best = 0;
  double nearest = INFINITY;
  for (int a = 0; a < 3; ++a)
    for (int high = 0; high < 2; ++high) {
      const double d = std::fabs(s.position[a] - (high ? b.hi[a] : b.lo[a]));
      if (d < nearest) nearest = d, best = a * 2 + high;
    }
  normal = glm::dvec3(0.0);
  normal[best / 2] = best % 2 ? 1.0 : -1.0;
  return s.box * 6 + best;
}

}  // namespace

TEST_CASE("surface pass: albedo by box, cos to the light's centre from the face normal, 0 on sky; vs ray casts", "[backend]") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::SurfaceRenderer renderer(gl_context(), tree);
  const pn::Scene scene = pn::make_scene(pn::fixtures::kScenes[0], 128);
  const int size = 64;
  const pn::Image seen = pn::read_float_texture(gl_context(), renderer.render(scene, size));
  const glm::dvec3 eye(glm::inverse(scene.camera_view())[3]);
  pn::Image expected(size, size, 4), face(size, size, 1, -1.0f);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto s = pn::ray_cast_surface_point(scene, x, y, size);
      if (!s) continue;
      glm::dvec3 normal;
      face.at(x, y) = static_cast<float>(face_of(scene, *s, normal));
      if (glm::dot(normal, eye - s->position) < 0) normal = -normal;
      const glm::vec3 albedo = s->box == 0 ? pn::kGroundAlbedo : pn::kBoxAlbedo;
      for (int c = 0; c < 3; ++c) expected.at(x, y, c) = albedo[c];
      const glm::dvec3 to_light = glm::normalize(glm::dvec3(scene.light_position) - s->position);
      expected.at(x, y, 3) = static_cast<float>(std::max(glm::dot(normal, to_light), 0.0));
    }
  // Off face edges (3x3 neighbours on the same face, or all sky), where the pixel centre cannot see another face.
  int compared = 0, sky = 0;
  for (int y = 1; y < size - 1; ++y)
    for (int x = 1; x < size - 1; ++x) {
      bool interior = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) interior = interior && face.at(x + dx, y + dy) == face.at(x, y);
      if (!interior) continue;
      ++compared, sky += face.at(x, y) < 0;
      INFO("pixel " << x << ", " << y << " face " << face.at(x, y));
      for (int c = 0; c < 3; ++c) CHECK(seen.at(x, y, c) == expected.at(x, y, c));
      CHECK(seen.at(x, y, 3) == Approx(expected.at(x, y, 3)).margin(1e-3));
    }
  CHECK(compared > size * size / 2);
  CHECK(sky > 0);
}
