// cascades.glsl and cascades.h on a real GL context against the definitions
// in double, and copies of them with one deliberate mistake each.
#include <catch2/catch.hpp>

#include "broken_copy.h"
#include "check/module_check.h"
#include "gl_test_context.h"

using pn::test::failing_named;

namespace {

const pn::ModuleCheck& cascades() { return pn::find_module_check("cascades"); }

// Every failing case's name contains `part`, and at least one fails.
void fails_only(const std::vector<pn::CaseResult>& results, const char* part) {
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!pn::test::named(r, part)) CHECK(r.comparison.pass);
  }
  CHECK(failing_named(results, part) > 0);
}

}  // namespace

TEST_CASE("cascades: splits, order, selection, blend, spheres, snaps and the fit's stability hold") {
  const auto results = pn::test::run_check(cascades(), PENUMBRA_GLSL_DIR);
  // 7 split cases; selection: 4 counts x 2 k x 3 bands x 2 fades x 2, plus the seam case where
  // band > 0 and m > 1 (3 x 2 x 2 x 2); sphere 2, snap 2; blend pass 4; the city's hard shadow 4,
  // its seams 2; path 3 counts x 4; pcf and fast on cascades in fragment shaders 2.
  CHECK(results.size() == 7 + 96 + 24 + 4 + 4 + 4 + 2 + 12 + 2);
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: an enlargement without the progression's halving fails the enlargement and hybrid cases only") {
  const pn::test::BrokenCopy copy("cascades.h", "excess / float(1 << clamp(i - 1, 0, 30))", "excess / float(clamp(i, 1, 30))");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(cascades(), copy.root());
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!pn::test::named(r, "enlargement") && !pn::test::named(r, "hybrid")) CHECK(r.comparison.pass);
  }
  CHECK(failing_named(results, "enlargement k_i") == 1);
  CHECK(failing_named(results, "hybrid split") == 1);
}

TEST_CASE("negative: a blend weight over the whole cascade instead of its band fails the weights and the seams") {
  const pn::test::BrokenCopy copy("cascades.glsl", "(viewDepth - bandStart) / (end - bandStart)",
                                  "(viewDepth - bandStart) / (end - start)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(cascades(), copy.root());
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!pn::test::named(r, "selection") && !pn::test::named(r, "blend pass") && !pn::test::named(r, "city") &&
        !pn::test::named(r, "seams"))
      CHECK(r.comparison.pass);
  }
  CHECK(failing_named(results, "blend pass") > 0);
  CHECK(failing_named(results, "no seam") > 0);
  CHECK(failing_named(results, "blend weight") > 0);
  CHECK(failing_named(results, "index and next") == 0);
}

TEST_CASE("negative: a snap that truncates instead of rounding fails the snap case only") {
  const pn::test::BrokenCopy copy("cascades.h", "floor(centreLight / texelSize + vec2(0.5f, 0.5f))",
                                  "floor(centreLight / texelSize)");
  REQUIRE(copy.found());
  fails_only(pn::test::run_check(cascades(), copy.root()), "snap: floor");
}

TEST_CASE("negative: a sphere centred without the field of view's term fails the sphere case") {
  const pn::test::BrokenCopy copy("cascades.h", "(sliceNear + sliceFar) * (1.0f + t2)", "(sliceNear + sliceFar)");
  REQUIRE(copy.found());
  fails_only(pn::test::run_check(cascades(), copy.root()), "slice sphere");
}

TEST_CASE("negative: a blend pass that reads cascade 0 for cascade 1 fails the blend pass, the city's hard shadow and its seams") {
  const pn::test::BrokenCopy copy("passes/cascade_blend.comp", "if (c == 1) return texelFetch(pnVisibility1, p, 0).r;",
                                  "if (c == 1) return texelFetch(pnVisibility0, p, 0).r;");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(cascades(), copy.root());
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!pn::test::named(r, "blend pass") && !pn::test::named(r, "city") && !pn::test::named(r, "seams"))
      CHECK(r.comparison.pass);
  }
  CHECK(failing_named(results, "blend pass") > 0);
  CHECK(failing_named(results, "no seams: Fast PCSS") == 1);
}

TEST_CASE("negative: a PCSS fragment shader reading its neighbour fails fast's cascaded fragment case, not pcf's") {
  // The stage reaches every cascade's call (CascadedTechnique passes it on): only the broken stage fails.
  const pn::test::BrokenCopy copy("passes/pcss_one_call.frag", "pnOneCallShade(ivec2(gl_FragCoord.xy), fetches)",
                                  "pnOneCallShade(ivec2(gl_FragCoord.xy) + ivec2(1, 0), fetches)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(cascades(), copy.root());
  CHECK(failing_named(results, "fast's call in fragment shaders") == 1);
  CHECK(failing_named(results, "pcf's call in fragment shaders") == 0);
  CHECK(pn::test::failing_cases(results) == 1);
}
