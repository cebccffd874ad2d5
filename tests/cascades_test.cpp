// The cascades' references worked by hand, the runner's formulas (cascades.h
// through glm) against them, and the cascade fit's promises and refusals.
#include <catch2/catch.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "cascades/cascade_fit.h"
#include "cascades/cascade_math.h"
#include "core/error.h"
#include "reference/cascades_reference.h"

using Catch::Matchers::Contains;

namespace {

pn::CascadeCamera street_camera() {
  pn::CascadeCamera camera;
  camera.view = glm::lookAt(glm::vec3(3, 1.7f, 8), glm::vec3(40, 0.5f, -30), glm::vec3(0, 1, 0));
  camera.fov_y_radians = 1.0, camera.aspect = 16.0 / 9.0, camera.near_plane = 0.5, camera.far_plane = 400;
  return camera;
}

const glm::vec3 kSun(-0.35f, -0.8f, -0.45f), kLo(-200, -1, -200), kHi(200, 60, 200);

}  // namespace

TEST_CASE("split references by hand: Eq. 7, the adaptive lambda, the progression and the gap") {
  // n = 1, f = 100, m = 2, lambda = 0.5: 0.5 * 1 * 10 + 0.5 * (1 + 99 / 2) = 5 + 25.25 = 30.25.
  CHECK(pn::practical_split_reference(0.5, 1, 100, 1, 2) == Approx(30.25).epsilon(1e-12));
  CHECK(pn::cascade_math::pnCascadePracticalSplit(0.5f, 1, 100, 1, 2) == Approx(30.25).epsilon(1e-6));
  CHECK(pn::cascade_math::pnCascadePracticalSplit(0.5f, 1, 100, 0, 2) == 1.0f);
  CHECK(pn::cascade_math::pnCascadePracticalSplit(0.5f, 1, 100, 2, 2) == 100.0f);
  // f/n = 10 and 100: 0.6; 10^2.5: 0.8; 1000 and 10^4: 1.
  for (const auto& [ratio, lambda] : {std::pair{10.0, 0.6}, {100.0, 0.6}, {std::pow(10.0, 2.5), 0.8}, {1000.0, 1.0}, {1e4, 1.0}}) {
    CHECK(pn::adaptive_lambda_reference(0.5, 0.5 * ratio) == Approx(lambda).epsilon(1e-12));
    CHECK(pn::cascade_math::pnCascadeAdaptiveLambda(0.5f, static_cast<float>(0.5 * ratio)) == Approx(lambda).margin(1e-6));
  }
  CHECK(pn::cascade_math::pnCascadeAdaptiveLambda(0.0f, 10.0f) == 0.6f);  // unusable planes
  // k = 4: 4, 2.5, 1.75 (the excess 3 halving); k < 1 is no enlargement.
  CHECK(pn::enlargement_reference(4, 1) == 4.0);
  CHECK(pn::enlargement_reference(4, 2) == 2.5);
  CHECK(pn::enlargement_reference(4, 3) == 1.75);
  CHECK(pn::cascade_math::pnCascadeEnlargement(4.0f, 3) == 1.75f);
  CHECK(pn::cascade_math::pnCascadeEnlargement(0.5f, 1) == 1.0f);
  // n = 1, f = 101, lambda = 0 (uniform), m = 2: C_1 = 51; k = 4 gives E_1 = 1 + 50 * 4 = 201,
  // past f: held at n + 0.9 (f - n) = 91 by the gap 0.1.
  const std::vector<double> hybrid = pn::hybrid_splits_reference(0, 1, 101, 2, 4, 0.1);
  REQUIRE(hybrid.size() == 3);
  CHECK(hybrid[0] == 1.0);
  CHECK(hybrid[1] == Approx(91.0).epsilon(1e-12));
  CHECK(hybrid[2] == 101.0);
  CHECK(pn::cascade_math::pnCascadeHybridSplit(0, 1, 101, 1, 2, 4, 0.1f) == Approx(91.0).epsilon(1e-6));
  // k = 2 leaves room: E_1 = 1 + 50 * 2 = 101 = f, held at 91 again; k = 1.5: 76, below the cap.
  CHECK(pn::cascade_math::pnCascadeHybridSplit(0, 1, 101, 1, 2, 1.5f, 0.1f) == Approx(76.0).epsilon(1e-6));
}

TEST_CASE("selection reference by hand: cascade index, band start and weight, the last cascade's fade") {
  const std::vector<double> splits{10, 50, 400};  // near 1
  CHECK(pn::cascade_choice_reference(5, 1, splits, 0.1, false).index == 0);
  CHECK(pn::cascade_choice_reference(5, 1, splits, 0.1, false).weight == 0.0);
  // Cascade 0 spans [1, 10): band 0.9 wide from 9.1; 9.55 is half-way.
  const auto half = pn::cascade_choice_reference(9.55, 1, splits, 0.1, false);
  CHECK(half.index == 0);
  CHECK(half.next == 1);
  CHECK(half.weight == Approx(0.5).epsilon(1e-12));
  CHECK(pn::cascade_choice_reference(10, 1, splits, 0.1, false).index == 1);  // a split belongs to the next cascade
  CHECK(pn::cascade_choice_reference(0.2, 1, splits, 0.1, false).index == 0);  // before near: the first
  // The last spans [50, 400): band from 365; 399 is 34/35 of the way, unless the last does not fade.
  CHECK(pn::cascade_choice_reference(399, 1, splits, 0.1, false).weight == 0.0);
  CHECK(pn::cascade_choice_reference(399, 1, splits, 0.1, true).weight == Approx(34.0 / 35.0).epsilon(1e-12));
  CHECK(pn::cascade_choice_reference(400, 1, splits, 0.1, true).index == 3);  // none
  CHECK(pn::cascade_choice_reference(NAN, 1, splits, 0.1, true).index == 3);
}

TEST_CASE("slice sphere by hand: centred where near and far corners are equally far, or on the far face") {
  // a = 1, b = 2, t = 0.5: c = 1.5 * 1.25 = 1.875; both corner distances sqrt(0.875^2 + 0.25) = sqrt(0.125^2 + 1).
  const pn::SphereReference s = pn::slice_sphere_reference(1, 2, 0.5, 0);
  CHECK(s.centre == Approx(1.875).epsilon(1e-9));
  CHECK(s.radius == Approx(std::sqrt(1.015625)).epsilon(1e-9));
  const glm::vec2 gpu_form = pn::cascade_math::pnCascadeSliceSphere(1, 2, 0.5f);
  CHECK(gpu_form.x == Approx(1.875).epsilon(1e-6));
  CHECK(gpu_form.y == Approx(std::sqrt(1.015625)).epsilon(1e-6));
  // a = 1, b = 3, t = 1: (a + b)(1 + t^2)/2 = 4 lies past b: centre 3, radius b t = 3.
  // (The largest distance is smooth at this minimum, so the search finds the centre to ~sqrt(eps).)
  const pn::SphereReference wide = pn::slice_sphere_reference(1, 3, 0.6, 0.8);
  CHECK(wide.centre == Approx(3.0).epsilon(1e-7));
  CHECK(wide.radius == Approx(3.0).epsilon(1e-9));
  CHECK(pn::cascade_math::pnCascadeSliceSphere(1, 3, 1).x == 3.0f);
  CHECK(pn::cascade_math::pnCascadeSnapTexels(glm::vec2(1.24f, -1.26f), 0.5f) == glm::vec2(2, -3));
}

TEST_CASE("cascade fit: splits in order, stable cascades snapped to whole texels, the slice inside each map") {
  pn::CascadeSettings settings;
  settings.count = 4, settings.enlargement = 3;
  const pn::CascadeCamera camera = street_camera();
  const std::vector<pn::Cascade> cascades = pn::fit_cascades(settings, camera, kSun, kLo, kHi);
  REQUIRE(cascades.size() == 4);
  CHECK(cascades.front().split_near == 0.5f);
  CHECK(cascades.back().split_far == 400.0f);
  for (size_t i = 0; i < cascades.size(); ++i) {
    const pn::Cascade& c = cascades[i];
    INFO("cascade " << i);
    CHECK(c.split_near < c.split_far);
    if (i > 0) CHECK(c.split_near == cascades[i - 1].split_far);
    if (i > 0) CHECK(c.fit_near < c.split_near);  // reaches back over the previous cascade's band
    CHECK(c.snapped_texels == glm::floor(c.snapped_texels));
    CHECK(c.texel_size == Approx(2 * c.radius / settings.map_size).epsilon(1e-6));
    if (i > 0) CHECK(c.texel_size > cascades[i - 1].texel_size);  // coarser with distance
    for (double z : {double(c.fit_near), double(c.split_far)})
      for (const glm::dvec3& corner : camera.corners_at(z)) {
        const glm::dvec3 m = c.map_position(corner, settings.map_size);
        CHECK(m.x > 0.5);  // at least the margin's half texel inside
        CHECK(m.x < settings.map_size - 0.5);
        CHECK(m.y > 0.5);
        CHECK(m.y < settings.map_size - 0.5);
        CHECK(m.z <= c.depth_far);  // (the range starts at the scene's nearest point; corners above the scene lie before it)
      }
  }
  // The first split k = 3 times further out than the practical split (lambda adaptive, 0.96 here).
  const double lambda = settings.effective_lambda(0.5, 400);
  CHECK(lambda == Approx(0.6 + 0.4 * (std::log10(800.0) - 2)).margin(1e-6));
  CHECK(cascades[0].split_far ==
        Approx(0.5 + 3 * (pn::practical_split_reference(lambda, 0.5, 400, 1, 4) - 0.5)).epsilon(1e-5));
}

TEST_CASE("cascade fit refuses bad settings, cameras and light directions with one line naming them") {
  const pn::CascadeCamera camera = street_camera();
  const auto refuses = [&](pn::CascadeSettings s, const char* message) {
    CHECK_THROWS_WITH(pn::fit_cascades(s, camera, kSun, kLo, kHi), Contains(message));
  };
  pn::CascadeSettings s;
  s.count = 0, refuses(s, "cascade count 0: expected 1 ... 4");
  s = {}, s.count = 5, refuses(s, "cascade count 5");
  s = {}, s.lambda = 1.5, refuses(s, "cascade lambda 1.5: expected 0 ... 1");
  s = {}, s.enlargement = 0.5, refuses(s, "cascade enlargement k 0.5: expected a finite number >= 1");
  s = {}, s.enlargement = INFINITY, refuses(s, "cascade enlargement k inf");
  s = {}, s.gap = 0, refuses(s, "cascade gap 0: expected 0.001 ... 0.9");
  s = {}, s.band = 1, refuses(s, "cascade blend band 1: expected 0 <= band < 1");
  s = {}, s.map_size = 2, refuses(s, "cascade map size 2: expected N >= 4");
  pn::CascadeCamera bad = camera;
  bad.far_plane = 0.25;
  CHECK_THROWS_WITH(pn::fit_cascades({}, bad, kSun, kLo, kHi), Contains("camera far 0.25: expected a finite number > near"));
  bad = camera, bad.fov_y_radians = NAN;
  CHECK_THROWS_WITH(pn::fit_cascades({}, bad, kSun, kLo, kHi), Contains("camera field of view nan"));
  CHECK_THROWS_WITH(pn::fit_cascades({}, camera, glm::vec3(0), kLo, kHi),
                    Contains("light direction (0, 0, 0): expected a finite, non-zero vector"));
}
