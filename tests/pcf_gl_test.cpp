// pcf.glsl on a real GL context against the definition in double, and copies
// of it with one deliberate mistake.
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

const pn::ModuleCheck& pcf() { return pn::find_module_check("pcf"); }

}  // namespace

TEST_CASE("pcf window scans equal the definition: whole, in bands of 1/7/128 rows, and bounded to 64 texels a side") {
  const auto results = pn::test::run_check(pcf(), PENUMBRA_GLSL_DIR);
  // fixtures × ((whole, bands, bounded) × (sides <= 16, > 16) × (counts, depth sum) + bilinear, without and with a
  // receiver plane, + the area-weighted window without and with a plane + the windows with a plane (counts, depth
  // sum)), and the leave-out case.
  CHECK(results.size() == std::size(pn::fixtures::kTextureFixtures) * (3 * 2 * 2 + 2 + 2 + 2) + 1);
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: a copy of pcf.glsl that lets -Inf texels occlude fails on the NaN/Inf fixture, and only there") {
  const pn::test::BrokenCopy copy("pcf.glsl", "return depth < threshold && depth > uintBitsToFloat(0xff800000u);",
                                  "return depth < threshold;");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(pcf(), copy.root(), pn::test::kQuick);  // its 3 fixtures (the suite's time)
  size_t nonfinite_failures = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (r.name.rfind("nonfinite ", 0) == 0) nonfinite_failures += r.comparison.pass ? 0 : 1;
    else CHECK(r.comparison.pass);
  }
  CHECK(nonfinite_failures > 0);
  CHECK(pn::test::failing_cases(results) == nonfinite_failures);
}

TEST_CASE("negative: a copy of pcf.glsl whose bands start one row early fails every banded case, no other") {
  const pn::test::BrokenCopy copy("pcf.glsl", "int rowStart = max(lo.y, firstRow);",
                                  "int rowStart = max(lo.y, firstRow - 1);");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(pcf(), copy.root(), pn::test::kQuick);  // its 3 fixtures (the suite's time)
  size_t banded = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "bands of") && named(r, "occluders, texels")) {
      ++banded;
      CHECK_FALSE(r.comparison.pass);  // rows counted twice: more texels
    } else if (!named(r, "bands of")) {
      CHECK(r.comparison.pass);  // a whole window starts at row 0: max(lo.y, -1) = lo.y
    }
  }
  CHECK(banded == 3 * 3);  // the quick run's 3 fixtures, and the plane windows' (banded 3 in 4)
  CHECK(pn::test::failing_cases(results) >= banded);
}

TEST_CASE("the bundles of pcf.glsl, pcf_query.comp and pcss_scan.comp compile with the GL driver") {
  for (const char* module : {"pcf.glsl", "passes/pcf_query.comp", "passes/pcss_scan.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}

TEST_CASE("negative: a bilinear PCF that weights the columns the wrong way round fails the bilinear cases, and only those") {
  const pn::test::BrokenCopy copy("pcf.glsl", "pn_pcfLitAt(depthMap, i + ivec2(1, 0), receiver, gradient, t), f.x)",
                                  "pn_pcfLitAt(depthMap, i + ivec2(1, 0), receiver, gradient, t), 1.0 - f.x)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(pcf(), copy.root(), pn::test::kQuick);  // its 3 fixtures (the suite's time)
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!named(r, "bilinear")) CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "bilinear") > 0);
}
