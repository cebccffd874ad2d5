// vsm.glsl on a real GL context against vsm_reference, and copies of it with
// one deliberate mistake each that must fail their cases and only those.
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/module_check.h"
#include "driver_bundle.h"
#include "fixture_images/texture_fixture.h"
#include "gl_test_context.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& vsm() { return pn::find_module_check("vsm"); }

}  // namespace

TEST_CASE("vsm moments, blurred moments, Chebyshev, reduction, depth-range bound and bleeding equal the reference") {
  const auto results = pn::test::run_check(vsm(), PENUMBRA_GLSL_DIR);
  // maps (fixtures at 37² and 64², the two-occluder map) × (moments, a blur case a channel, 4 query cases),
  // for VSM (2 channels), EVSM-2 (2) and EVSM-4 (4); 3 bleeding cases a kind; and VSM at radius 0
  // on the noise and step-edge maps (2 sizes each).
  const size_t maps = std::size(pn::fixtures::kTextureFixtures) * 2 + 1;
  CHECK(results.size() == maps * ((1 + 2 + 4) + (1 + 2 + 4) + (1 + 4 + 4)) + 3 * 3 + 4 * (1 + 2 + 4));
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: a copy with an absolute minimum variance fails the Chebyshev cases, not the moments or bound") {
  const pn::test::BrokenCopy copy("variance_bound.glsl", "max(minVariance, 0.0) * (mu * mu)", "max(minVariance, 0.0)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(vsm(), copy.root());
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, ": moments vs") || named(r, ": blurred moment ") || named(r, "depth-range bound at"))
      CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "Chebyshev bound on the blurred moments") > 0);
}

TEST_CASE("negative: a copy whose depth-range bound calls a receiver at the window's min shadowed fails only the bound cases") {
  const pn::test::BrokenCopy copy("variance_bound.glsl", "if (t <= minMax.x) return PN_VSM_BOUND_LIT;",
                                  "if (t < minMax.x) return PN_VSM_BOUND_LIT;");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(vsm(), copy.root());
  size_t bound_failures = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "depth-range bound at")) bound_failures += r.comparison.pass ? 0 : 1;
    else CHECK(r.comparison.pass);  // at t = min, t <= mu: the Chebyshev bound is 1 too
  }
  CHECK(bound_failures == (std::size(pn::fixtures::kTextureFixtures) * 2 + 1) * 3 + 4);  // + VSM at radius 0
}

TEST_CASE("negative: a copy with a wrong EVSM warp fails EVSM's moment cases and no VSM case") {
  const pn::test::BrokenCopy copy("variance_bound.glsl", "return vec2(exp(c.x * x), -exp(-c.y * x));",
                                  "return vec2(exp(1.001 * c.x * x), -exp(-c.y * x));");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(vsm(), copy.root());
  size_t evsm_moments = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, " vsm:") || named(r, " vsm light")) CHECK(r.comparison.pass);
    if (named(r, "evsm") && named(r, ": moments vs the definition")) {
      ++evsm_moments;
      CHECK_FALSE(r.comparison.pass);
    }
  }
  CHECK(evsm_moments == (std::size(pn::fixtures::kTextureFixtures) * 2 + 1) * 2);
}

TEST_CASE("negative: a copy that lets non-finite depths into the moments fails on the NaN/Inf fixture only") {
  const pn::test::BrokenCopy copy("variance_bound.glsl", "float d = pn_vsmIsFinite(depth) ? depth : farDepth;",
                                  "float d = depth;");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(vsm(), copy.root());
  size_t nonfinite = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (r.name.rfind("nonfinite ", 0) == 0 && named(r, " vsm: moments")) {
      ++nonfinite;
      CHECK_FALSE(r.comparison.pass);
    } else if (r.name.rfind("nonfinite ", 0) != 0) {
      CHECK(r.comparison.pass);
    }
  }
  CHECK(nonfinite == 2);
}

TEST_CASE("negative: a copy without the bleeding reduction fails the reduction and bleeding cases") {
  const pn::test::BrokenCopy copy("variance_bound.glsl", "float a = clamp(amount, 0.0, float(PN_VSM_MAX_BLEEDING_REDUCTION));",
                                  "float a = clamp(0.0 * amount, 0.0, float(PN_VSM_MAX_BLEEDING_REDUCTION));");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(vsm(), copy.root());
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, ": moments vs") || named(r, ": blurred moment ") || named(r, "Chebyshev bound on") ||
        named(r, "depth-range bound at"))
      CHECK(r.comparison.pass);
  }
  CHECK(pn::test::failing_named(results, "bleeding reduction linstep") > 0);
  CHECK(pn::test::failing_named(results, "the reduction lowers") == 3);
}

TEST_CASE("the bundles of vsm.glsl, vsm_moments.comp and vsm_query.comp compile with the GL driver") {
  for (const char* module : {"vsm.glsl", "passes/vsm_moments.comp", "passes/vsm_query.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}
