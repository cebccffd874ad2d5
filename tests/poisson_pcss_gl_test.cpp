// poisson_pcss.glsl on a real GL context against the definition in double,
// and copies of it with one deliberate mistake.
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/module_check.h"
#include "fixture_images/texture_fixture.h"
#include "gl/objects.h"
#include "driver_bundle.h"
#include "gl_test_context.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& poisson() { return pn::find_module_check("poisson_pcss"); }

}  // namespace

TEST_CASE("Poisson samples equal the definition: block and constant disks, rotation off and on, clamped counts") {
  const auto results = pn::test::run_check(poisson(), PENUMBRA_GLSL_DIR);
  // fixtures × (block, constant disk) × ((rotation off, on) × (counts, depth sum) + the sums' ratios), and the
  // leave-out case.
  CHECK(results.size() == std::size(pn::fixtures::kTextureFixtures) * 2 * (2 * 2 + 1) + 1);
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: a copy of poisson_pcss.glsl that turns samples the wrong way fails with rotation on, only") {
  const pn::test::BrokenCopy copy("poisson_pcss.glsl", "rotation.y * offset.x + rotation.x * offset.y",
                                  "-rotation.y * offset.x + rotation.x * offset.y");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(poisson(), copy.root());
  size_t rotated = 0, failing = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "rotation on") && named(r, "occluders, samples")) {
      ++rotated;
      failing += r.comparison.pass ? 0 : 1;
    } else if (named(r, "rotation off")) {
      CHECK(r.comparison.pass);  // (1, 0): -0 * x + y = y
    }
  }
  CHECK(rotated == std::size(pn::fixtures::kTextureFixtures) * 2);
  CHECK(failing >= rotated - 1);  // the constant fixture cannot tell, every other one must
  CHECK(pn::test::failing_cases(results) > 0);
}

TEST_CASE("negative: a copy of poisson_pcss.glsl whose in-place loop takes one sample too many fails there only") {
  // The second `if (i >= count) break;` is pnPoissonOcclusionDisk's.
  const std::string from = "    if (i >= count) break;\n    sums = pnPoissonAddSample(depthMap, centre, radius, PN_POISSON_DISK_ARRAY[i]";
  const std::string to = "    if (i > count) break;\n    sums = pnPoissonAddSample(depthMap, centre, radius, PN_POISSON_DISK_ARRAY[i]";
  const pn::test::BrokenCopy copy("poisson_pcss.glsl", from, to);
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(poisson(), copy.root());
  size_t in_place = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if ((named(r, "constant disk") || named(r, "block disk")) && named(r, "occluders, samples")) {
      ++in_place;
      CHECK_FALSE(r.comparison.pass);  // counts below the array's length take one sample more
    } else if (named(r, "parameter disk")) {
      CHECK(r.comparison.pass);
    }
  }
  CHECK(in_place == std::size(pn::fixtures::kTextureFixtures) * 4);
}

TEST_CASE("the bundles of poisson_pcss.glsl, poisson_pcss_query.comp and pcss_poisson.comp compile with the GL driver") {
  for (const char* module : {"poisson_pcss.glsl", "passes/poisson_pcss_query.comp", "passes/pcss_poisson.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}
