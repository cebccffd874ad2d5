// The physical reference and the surface pass on a real GL context: the
// physical_reference check passes, copies of hard_shadow.frag with the
// comparison inverted or the bias's sign flipped fail it, a point light is
// one hard shadow however often it is sampled, bad parameters are refused,
// and the surface pass's albedo and cosine equal a CPU ray cast's off edges.
#include <catch2/catch.hpp>

#include <cmath>

#include "broken_copy.h"
#include "check/compare.h"
#include "core/error.h"
#include "gl/texture.h"
#include "hand_scene.h"
#include "passes/physical_reference_pass.h"
#include "passes/surface_pass.h"
#include "scene/visibility_reference.h"

using pn::test::BrokenCopy;
using pn::test::check_all_pass;
using pn::test::failing_cases;
using pn::test::gl_context;
using pn::test::run_check;

namespace {
const char* const kComparison = "occluded = occluder < receiverDepth - pnParams.bias;";
}

TEST_CASE("physical_reference: averaged hard shadows equal the segment tests within one sample or the texel range") {
  check_all_pass(run_check(pn::find_module_check("physical_reference"), PENUMBRA_GLSL_DIR));
}

TEST_CASE("negative: a hard shadow with the depth comparison inverted fails the physical_reference check") {
  const BrokenCopy copy("passes/hard_shadow.frag", kComparison, "occluded = occluder > receiverDepth - pnParams.bias;");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("physical_reference"), copy.root())) > 0);
}

TEST_CASE("negative: a hard shadow with the bias's sign flipped (self-shadowing) fails the physical_reference check") {
  const BrokenCopy copy("passes/hard_shadow.frag", kComparison, "occluded = occluder < receiverDepth + pnParams.bias;");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("physical_reference"), copy.root())) > 0);
}

TEST_CASE("physical reference: a light of width 0 gives one hard shadow, the same for 1 and 3x3 samples, 0 or 1") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::PhysicalReferenceRenderer renderer(gl_context(), tree);
  const pn::Scene point_light = pn::test::table_scene(64, 0.0);
  const pn::Image one = pn::read_float_texture(gl_context(), renderer.render(point_light, 32, 1, 0.02f), 32, 32, 1);
  const pn::Image nine = pn::read_float_texture(gl_context(), renderer.render(point_light, 32, 3, 0.02f), 32, 32, 1);
  const pn::Comparison same = pn::compare(one, nine, pn::Tolerance::exact());
  INFO(same.where(pn::Tolerance::exact()));
  CHECK(same.pass);
  int shadowed = 0;
  for (float v : one.texels) {
    CHECK((v == 0.0f || v == 1.0f));
    shadowed += v == 0.0f;
  }
  CHECK(shadowed > 0);  // the table's shadow is on screen
}

TEST_CASE("negative: the physical reference refuses samples per side 0 and 65, screen 0, negative or NaN bias") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::PhysicalReferenceRenderer renderer(gl_context(), tree);
  const pn::Scene scene = pn::test::table_scene();
  CHECK_THROWS_WITH(renderer.render(scene, 16, 0, 0.02f),
                    Catch::Contains("light samples per side 0: expected 1 to 64"));
  CHECK_THROWS_WITH(renderer.render(scene, 16, 65, 0.02f), Catch::Contains("light samples per side 65"));
  CHECK_THROWS_WITH(renderer.render(scene, 0, 4, 0.02f), Catch::Contains("screen size 0: expected at least 1"));
  CHECK_THROWS_WITH(renderer.render(scene, 16, 4, -0.5f),
                    Catch::Contains("shadow bias -0.5: expected a finite number >= 0"));
  CHECK_THROWS_WITH(renderer.render(scene, 16, 4, std::nanf("")), Catch::Contains("shadow bias nan"));
}

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

TEST_CASE("surface pass: albedo by box, cos to the light's centre from the face normal, 0 on sky; vs ray casts") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::SurfaceRenderer renderer(gl_context(), tree);
  const pn::Scene scene = pn::make_scene(pn::fixtures::kScenes[0], 128);
  const int size = 64;
  const pn::Image seen = pn::read_float_texture(gl_context(), renderer.render(scene, size), size, size, 4);
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
