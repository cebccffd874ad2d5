// savsm.glsl on a real GL context against savsm_reference, and copies of it
// with one deliberate mistake each that must fail their cases and only those.
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/module_check.h"
#include "driver_bundle.h"
#include "gl_test_context.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& savsm() { return pn::find_module_check("savsm"); }

// The check's maps with --quick (64², 256²; the 1024² map runs the same programs on more texels) and
// configurations (5; the one without bound and reduction adds the upper-bound case). The broken
// copies run the check so; the library's whole run is cli_check_all_gl's.
constexpr size_t kMaps = 2, kConfigs = 5, kCasesPerConfig = 9;

}  // namespace

// The library's own run of the check is cli_check_all_gl's (every case must pass); this copy holds
// the case count too.
TEST_CASE("negative: a copy whose Chebyshev blocker adds the mean fails the table blocker's cases only") {
  const pn::test::BrokenCopy copy("savsm.glsl", "/ (t - s.mean), near, t);", "/ (t + s.mean), near, t);");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(savsm(), copy.root(), pn::test::kQuick);
  CHECK(results.size() == kMaps * (kConfigs * kCasesPerConfig + 2));  // + exports/savsm, the defaults
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!named(r, "table blocker")) CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "table blocker: blocker") == kMaps);
}

TEST_CASE("negative: a copy whose filter square is a texel too wide fails the filter square cases") {
  const pn::test::BrokenCopy copy("savsm.glsl", "r.filterRect = pnRegionSquare(receiver.xy, r.filterSide, n);",
                                  "r.filterRect = pnRegionSquare(receiver.xy, r.filterSide + 1.0, n);");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(savsm(), copy.root(), pn::test::kQuick);
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "search square") || named(r, ": blocker") || named(r, "filter side")) CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "filter square vs pcss_square") == kMaps * kConfigs);
}

TEST_CASE("negative: a copy that reads the filter's moments twice fails the fetch counts only") {
  const pn::test::BrokenCopy copy(
      "savsm.glsl", "PnSavsmStats f = pnSavsmRectStats(table, r.filterRect, unitRange);",
      "PnSavsmStats f = pnSavsmRectStats(table, r.filterRect, unitRange); f = pnSavsmRectStats(table, r.filterRect, unitRange);");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(savsm(), copy.root(), pn::test::kQuick);
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (!named(r, "texel fetches per receiver") && !named(r, "constant cost")) CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "texel fetches per receiver") == kMaps * kConfigs);
}

TEST_CASE("negative: a copy of summed_area.glsl whose variance skips the exact centring fails the variance cases") {
  const pn::test::BrokenCopy copy("summed_area.glsl", "pn_summedAreaUnsignedToFloat(centred) / m.texels - d * d",
                                  "pn_summedAreaUnsignedToFloat(s.zw) / m.texels - (float(centre) + d) * (float(centre) + d)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(savsm(), copy.root(), pn::test::kQuick);
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "search square") || named(r, "filter mean")) CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "filter variance vs brute force") > 0);
}

TEST_CASE("the bundles of savsm.glsl, savsm_shade.comp and savsm_query.comp compile with the GL driver") {
  for (const char* module : {"savsm.glsl", "passes/savsm_shade.comp", "passes/savsm_query.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}
