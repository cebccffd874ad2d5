// summed_area.glsl on a real GL context against direct box sums, and copies
// of it with one deliberate mistake.
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/module_check.h"
#include "driver_bundle.h"
#include "fixture/texture_fixture.h"
#include "gl_test_context.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& summed_area() { return pn::find_module_check("summed_area"); }

constexpr size_t kSizes = 6, kRanges = 4;
constexpr const char* kFixed = ": fixed-point sum";
constexpr const char* kFloat = ": [0] depth sum";

bool tiny(const pn::CaseResult& r) { return named(r, " 1x1, "); }
bool offset(const pn::CaseResult& r) { return named(r, "depth 1000 + v"); }

}  // namespace

TEST_CASE("summed_area rectangle sums equal direct box sums: 64-bit sums and counts exact, float sums within bound") {
  const auto results = pn::test::run_check(summed_area(), PENUMBRA_GLSL_DIR);
  // fixtures × sizes × ranges × (fixed point, float).
  CHECK(results.size() == std::size(pn::fixtures::kTextureFixtures) * kSizes * kRanges * 2);
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: a copy of summed_area.glsl whose bottom-left corner is one row high fails every map from 3x5 on") {
  const pn::test::BrokenCopy copy("summed_area.glsl", "texelFetch(table, ivec2(lo.x, hi.y), 0)",
                                  "texelFetch(table, ivec2(lo.x, max(hi.y - 1, lo.y)), 0)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(summed_area(), copy.root());
  size_t fixed = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, kFixed) && !tiny(r)) {
      ++fixed;
      CHECK_FALSE(r.comparison.pass);  // the finite count is off wherever x0 > 0 and the row above holds a texel
    }
  }
  CHECK(fixed == std::size(pn::fixtures::kTextureFixtures) * (kSizes - 1) * kRanges);
  CHECK(pn::test::failing_cases(results) >= fixed);
}

TEST_CASE("negative: a copy of summed_area.glsl that drops the carry into the high word fails at offset 1000, never on 1x1 maps") {
  const pn::test::BrokenCopy copy("summed_area.glsl", "a.y + b.y + carry", "a.y + b.y");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(summed_area(), copy.root());
  size_t large_offset = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (tiny(r)) CHECK(r.comparison.pass);  // 0 + q and q - 0 never carry
    // At F 20, q ~ 2^30 a texel: the low word overflows every few texels. (At F 40 a depth near 1000 is a
    // multiple of 2^26 steps, and of 2^32 on the constant, step and impulse fixtures: no carry to lose there.)
    if (offset(r) && !named(r, "F 40") && named(r, kFixed) &&
        (named(r, " 100x37, ") || named(r, " 257x257, ") || named(r, " 1024x1024, "))) {
      ++large_offset;
      CHECK_FALSE(r.comparison.pass);
    }
  }
  CHECK(large_offset == std::size(pn::fixtures::kTextureFixtures) * 3);
  CHECK(pn::test::failing_cases(results) >= large_offset);
}

TEST_CASE("negative: a copy of summed_area.glsl that takes the four-corner difference in float fails at offset 1000, "
          "its integer sums still exact") {
  const pn::test::BrokenCopy copy(
      "summed_area.glsl", "r.sum = pnSummedAreaFixedToFloat(s.xy);",
      "r.sum = pnSummedAreaFixedToFloat(bottomRight.xy) + pnSummedAreaFixedToFloat(topLeft.xy) - "
      "pnSummedAreaFixedToFloat(topRight.xy) - pnSummedAreaFixedToFloat(bottomLeft.xy);");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(summed_area(), copy.root());
  size_t large_offset = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, kFixed) || tiny(r)) CHECK(r.comparison.pass);  // one corner of a 1x1 map is non-zero: no cancellation
    if (offset(r) && named(r, kFloat) && (named(r, " 257x257, ") || named(r, " 1024x1024, "))) {
      ++large_offset;
      CHECK_FALSE(r.comparison.pass);  // prefixes of ~10^8..10^9 carry 8..64 units of float rounding
    }
  }
  CHECK(large_offset == std::size(pn::fixtures::kTextureFixtures) * 2 * 2);
  CHECK(pn::test::failing_cases(results) >= large_offset);
}

TEST_CASE("the bundles of summed_area.glsl, summed_area_build.comp and summed_area_query.comp compile with the GL driver") {
  for (const char* module : {"summed_area.glsl", "passes/summed_area_build.comp", "passes/summed_area_query.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}
