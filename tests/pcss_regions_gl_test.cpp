// pcss_regions on a real GL context against its CPU definition, copies of it
// with one deliberate mistake each, and issue 11's lit-coverage property (the
// window modes' lit decision, SPEC §4.7 Step 3).
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/pcss_regions_check.h"

using pn::test::BrokenCopy;
using pn::test::failing_cases;
using pn::test::run_check;

using pn::test::failing_named;
using pn::test::named;

namespace {

const pn::ModuleCheck& regions() { return pn::find_module_check("pcss_regions"); }


}  // namespace

TEST_CASE("negative: a copy of pcss_regions.glsl with half the filter side fails the filter sides, and nothing else") {
  const BrokenCopy copy("pcss_regions.glsl", "float side = scale * pnLightPenumbraTexels(",
                        "float side = 0.5 * scale * pnLightPenumbraTexels(");
  REQUIRE(copy.found());
  const auto results = run_check(regions(), copy.root());
  // The library's run of every check is cli_check_all_gl's (it must pass); this copy, which may
  // fail the filter entries only, holds the case count: 12 maps x ((3 modes + the mip chain's
  // search) x 3 + the counted searches' refinements + the property) + 3 lights x 3 (filter) + 1
  // (given entries) + tall_blocker ((3 modes + the mip chain, and the mip chain over squares with
  // area-weighted edges) x (3 + the property), and the mip chain's search with a receiver plane x 3)
  // + boxes (the property's far field: the window mode and the mip chain) + the staircases (the pyramid's entries
  // and sides; the mip chain's and its refinements) + the left-out bound.
  CHECK(results.size() == 12 * 14 + 9 + 1 + 20 + 3 + 2 + 2 + 3 + 1);
  CHECK(failing_named(results, "filter entries") >= 2);  // the sides of the two lights with a width
  for (const auto& r : results)
    if (!named(r, "filter entries")) CHECK(r.comparison.pass);
  CHECK(failing_cases(results) == failing_named(results, "filter entries"));
}

TEST_CASE("negative: a lit decision that lets a texel at exactly d - bias occlude fails the search decisions") {
  const BrokenCopy copy("pcss_regions.glsl", "if (!(zmin < highestThreshold)) return",
                        "if (!(zmin <= highestThreshold)) return");
  REQUIRE(copy.found());
  const auto results = run_check(regions(), copy.root(), pn::test::kQuick);
  CHECK(failing_named(results, "lit decisions") > 0);  // receivers at the depth of the texel under them, bias 0
  CHECK(failing_cases(results) > 0);
}

TEST_CASE("negative: a lit decision over the square of the region's shorter side fails in every mode, "
          "the lit-coverage property included") {
  const BrokenCopy copy("pcss_regions_pyramid.glsl", "max(r.size.x, r.size.y)", "min(r.size.x, r.size.y)");
  REQUIRE(copy.found());
  const auto results = run_check(regions(), copy.root(), pn::test::kQuick);
  for (const char* mode : {"exact region: ", "window region: ", "centred region: "})
    CHECK(failing_named(results, mode) > 0);  // clipped regions at the map's edges
  CHECK(failing_named(results, "although a texel can shadow them") > 0);
  for (const auto& r : results)
    if (named(r, "filter entries")) CHECK(r.comparison.pass);
}

// SPEC §4.7 Step 3 / issue 11 item 0: in every region mode the lit decision
// reads a square covering the whole search region, so it misses no blocker —
// reading the rounded-down power-of-two window instead marked 403 (window) and
// 352 (centred) shadowable receivers of this scene lit.
TEST_CASE("every region mode's lit decision on the tall-blocker scene misses no receiver a texel can shadow") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::CheckOptions options;
  for (pn::RegionMode mode : {pn::RegionMode::window, pn::RegionMode::exact, pn::RegionMode::centred}) {
    const pn::LitCoverage c = pn::pcss_regions_lit_coverage({pn::test::gl_context(), tree, options}, mode);
    INFO(c.result.name << ": " << c.result.comparison.where(c.result.tolerance));
    CHECK(c.violations == 0);
    CHECK(c.shadowable > 0);  // the scene has receivers to miss
    CHECK(c.lit > 0);
  }
}

TEST_CASE("negative: a lit decision that reads the power-of-two window marks shadowable receivers of the "
          "tall-blocker scene lit") {
  // The literal window of the entry, as the paper's Step 3 read it before issue 11.
  const BrokenCopy copy("pcss_regions_pyramid.glsl", "  PnRect r = pnEntryRect(entry, n);\n  if (r.size.x == 0 || r.size.y == 0) return pn_pyramidFar();\n  return pnPyramidSquareMinMax(pyramid, r.origin, max(r.size.x, r.size.y)).x;",
                        "  PnWindow w = pnEntryWindow(entry, n, PN_REGION_WINDOW);\n  return pnPyramidSquareMinMax(pyramid, w.origin, w.side).x;");
  REQUIRE(copy.found());
  const pn::SourceTree tree(copy.root());
  const pn::CheckOptions options;
  // Tall blocker: 403 of 8,561 lit receivers; boxes at 512²: 258, on the far boxes' walls (issue 11 item 6).
  for (const char* scene : {"tall_blocker", "boxes"}) {
    const pn::LitCoverage c = pn::pcss_regions_lit_coverage({pn::test::gl_context(), tree, options}, pn::RegionMode::window, scene);
    INFO(scene << ": " << c.violations << " of " << c.lit << " lit receivers a texel can shadow");
    CHECK(c.violations > 0);
  }
}
