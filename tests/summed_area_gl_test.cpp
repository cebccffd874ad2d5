// summed_area.glsl on a real GL context against direct box sums, and copies
// of it with one deliberate mistake.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "broken_copy.h"
#include "check/module_check.h"
#include "check/summed_area_check.h"
#include "driver_bundle.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "gl_test_context.h"
#include "pass_runners/summed_area_pass.h"
#include "reference/summed_area_reference.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& summed_area() { return pn::find_module_check("summed_area"); }

// One half of the check on a glsl root: the depth-sum table's cases or the moments tables'.
std::vector<pn::CaseResult> run_half(std::vector<pn::CaseResult> (*half)(const pn::CheckEnvironment&),
                                     const std::filesystem::path& root) {
  const pn::SourceTree tree(root);
  const pn::CheckOptions options;
  return half({pn::test::gl_context(), tree, options});
}
std::vector<pn::CaseResult> depth_cases(const std::filesystem::path& root) {
  return run_half(&pn::summed_area_depth_cases, root);
}

constexpr size_t kSizes = 6, kRanges = 4;
constexpr const char* kFixed = ": fixed-point sum";
constexpr const char* kFloat = ": [0] depth sum";

bool tiny(const pn::CaseResult& r) { return named(r, " 1x1, "); }
bool offset(const pn::CaseResult& r) { return named(r, "depth 1000 + v"); }

}  // namespace

TEST_CASE("summed_area rectangle sums equal direct box sums: 64-bit sums and counts exact, float sums within bound; "
          "the moments tables' cases pass too") {
  const auto results = pn::test::run_check(summed_area(), PENUMBRA_GLSL_DIR);
  // Depth sums: fixtures × sizes × ranges × (fixed point, float). Moments: 5 cases a map (every
  // fixture at 3 small sizes, noise at B 12, noise and boxes at 3 large sizes; the float table's
  // border one of them), a headline case per large size, the refusals.
  const size_t fixtures = std::size(pn::fixtures::kTextureFixtures);
  CHECK(results.size() == fixtures * kSizes * kRanges * 2 + 5 * (fixtures * 3 + 1 + 2 * 3) + 3 + 1);
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: a copy of summed_area.glsl whose bottom-left corner is one row high fails every map from 3x5 on") {
  const pn::test::BrokenCopy copy("summed_area.glsl", "pn_summedAreaFetch(table, ivec2(lo.x, hi.y))",
                                  "pn_summedAreaFetch(table, ivec2(lo.x, max(hi.y - 1, lo.y)))");
  REQUIRE(copy.found());
  const auto results = depth_cases(copy.root());
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
  const auto results = depth_cases(copy.root());
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
  const auto results = depth_cases(copy.root());
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

// ---- Moments tables ----------------------------------------------------------

namespace {

constexpr const char* kMomentSums = ": moments tables, [0..2] sum of q";
constexpr const char* kFixedVsQuantised = ": fixed table vs the exact moments of q";
constexpr const char* kFixedVsTrue = ": fixed table vs the true x";
constexpr const char* kFloatVsTrue = ": float table vs the true x";
constexpr size_t kMomentMaps = std::size(pn::fixtures::kTextureFixtures) * 3 + 1 + 2 * 3;

bool large(const pn::CaseResult& r) {
  return named(r, " 512x512, ") || named(r, " 1024x1024, ") || named(r, " 2048x2048, ");
}

std::vector<pn::CaseResult> moments_cases(const std::filesystem::path& root) {
  return run_half(&pn::summed_area_moments_cases, root);
}

}  // namespace

TEST_CASE("negative: a copy of summed_area.glsl whose moments variance drops the exact centring (S2/n - (S1/n)^2 in "
          "float) fails the fixed variance at every large map, against the true x on the boxes at 1024^2 and 2048^2") {
  const pn::test::BrokenCopy copy(
      "summed_area.glsl",
      "  m.variance = max(pn_summedAreaUnsignedToFloat(centred) / m.texels - d * d, 0.0) * (scale * scale);",
      "  float e1 = pn_summedAreaSignedToFloat(s.xy) / m.texels * scale;\n"
      "  m.variance = max(pn_summedAreaUnsignedToFloat(s.zw) / m.texels * (scale * scale) - e1 * e1, 0.0);");
  REQUIRE(copy.found());
  const auto results = moments_cases(copy.root());
  size_t quantised = 0, boxes = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, kMomentSums) || named(r, kFloatVsTrue) || r.headline) CHECK(r.comparison.pass);  // sums untouched
    if (named(r, kFixedVsQuantised) && large(r)) {
      ++quantised;
      CHECK_FALSE(r.comparison.pass);  // E[x^2] and E[x]^2 ~ 0.1, each rounded: errors of ~1e-8 against bounds of 8u var
      CHECK(r.comparison.channel == 1);
    }
    if (named(r, kFixedVsTrue) && named(r, "boxes ") && (named(r, " 1024x1024, ") || named(r, " 2048x2048, "))) {
      ++boxes;
      CHECK_FALSE(r.comparison.pass);  // flat box tops: variance 0, observed ~1e-8 against e^2 = 4e-12
      CHECK(r.comparison.channel == 1);
    }
  }
  CHECK(quantised == 6);
  CHECK(boxes == 2);
  CHECK(pn::test::failing_cases(results) >= quantised + boxes);
}

TEST_CASE("negative: a copy of summed_area.glsl whose moment sums read the bottom-left corner a row high fails the "
          "exact sums on every map, the float table's cases still pass") {
  const pn::test::BrokenCopy copy("summed_area.glsl", "pn_summedAreaFetch(table, c.xw)));",
                                  "pn_summedAreaFetch(table, ivec2(c.x, max(c.w - 1, c.y)))));");
  REQUIRE(copy.found());
  const auto results = moments_cases(copy.root());
  size_t exact = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, kFloatVsTrue)) CHECK(r.comparison.pass);
    if (named(r, kMomentSums)) {
      ++exact;
      CHECK_FALSE(r.comparison.pass);  // every map has a rectangle with x0 > 0 over texels (1x1: from (1, -1), 0x2)
    }
  }
  CHECK(exact == kMomentMaps);
  CHECK(pn::test::failing_cases(results) >= exact);
}

TEST_CASE("the float moments table at 2048^2 loses the 1x1 means at its far corner (worst error > 1e-2), the fixed "
          "point keeps every one within e") {
  const pn::Context& context = pn::test::gl_context();
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const int n = 2048;
  pn::Image depth = pn::generate_fixture(pn::find_fixture("noise"), n, n);
  for (float& d : depth.texels) d = 20.0f + 20.0f * d;  // x in [0.19, 0.40]
  const pn::UnitRange unit = pn::unit_range(1.0, 100.0);
  const pn::SummedAreaMomentsReference reference(depth, {1.0, 100.0, unit.offset, unit.scale});
  std::vector<pn::Rect> rects;
  for (int k = 0; k < 64; ++k) rects.push_back({n - 1 - k, n - 1, 1, 1}), rects.push_back({n - 1, n - 2 - k, 1, 1});
  const pn::SummedAreaMomentsPass pass(context, tree);
  const std::unique_ptr<pn::DeviceTexture> texture = context.upload(depth);
  const auto fixed = pass.query(pass.build(*texture, n, n, pn::MomentsTableKind::fixed, unit), rects);
  const auto floating = pass.query(pass.build(*texture, n, n, pn::MomentsTableKind::floating, unit), rects);
  double fixed_worst = 0.0, float_worst = 0.0;
  for (size_t k = 0; k < rects.size(); ++k) {
    const auto s = reference.sums(rects[k]);
    fixed_worst = std::max(fixed_worst, std::fabs(fixed[k].mean - s.mean));
    float_worst = std::max(float_worst, std::fabs(floating[k].mean - s.mean));
    CHECK(std::fabs(floating[k].mean - s.mean) <= reference.float_bound(s).mean);  // large, but within its bound
  }
  INFO("worst 1x1 mean error at the far corner of a 2048^2 noise map: fixed " << fixed_worst << ", float " << float_worst);
  CHECK(fixed_worst <= reference.texel_bound());
  // The far prefixes hold about 2^22 · (−0.2) ≈ −8·10^5, whose float spacing is 2^-4; 4094 additions
  // each rounded to it: measured 0.057, against a value of x − 1/2 ≈ −0.2.
  CHECK(float_worst > 1e-2);
}

TEST_CASE("the bundles of summed_area.glsl and its build, query and moments query passes compile with the GL driver") {
  for (const char* module : {"summed_area.glsl", "passes/summed_area_build.comp", "passes/summed_area_query.comp",
                             "passes/summed_area_moments_query.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}
