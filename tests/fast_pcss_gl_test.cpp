// The one calls (fast_pcss.glsl's pnFastPcss, poisson_pcss.glsl's
// pnPoissonPcss) on a real GL context: compute and fragment stage against the
// staged passes and the CPU's exact PCSS, and copies with one mistake.
#include <catch2/catch.hpp>

#include "broken_copy.h"
#include "check/module_check.h"
#include "gl_test_context.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& fast_pcss() { return pn::find_module_check("fast_pcss"); }

}  // namespace

TEST_CASE("the one calls equal the staged passes in compute and fragment stage, and exact PCSS with everything off") {
  const auto results = pn::test::run_check(fast_pcss(), PENUMBRA_GLSL_DIR);
  // 3 scenes × 15 settings × (compute vs staged, fragment vs compute) + 3 scenes × 6 settings with a receiver plane ×
  // fragment vs compute (the staged passes take no plane) + 3 scenes × 2 stages vs the CPU × (all off and exact, and
  // with area-weighted edges all off, exact and HQEPCSS at leaf 1, without the plane; all off, exact and HQEPCSS at
  // leaf 1 with it) + 3 scenes × 3 settings (the shipped walk's 2, the node budget's) × 3 counts vs
  // their definition.
  CHECK(results.size() == 3 * 15 * 2 + 3 * 6 + 3 * 2 * (5 + 3) + 3 * 3 * 3);
  pn::test::check_all_pass(results);
}

TEST_CASE("negative: a copy that halves Fast PCSS's occluded fraction fails in both stages, the rest passes") {
  // (traversal.glsl's pnTraversalOccludedFraction: only fast_pcss.glsl's call calls it)
  const pn::test::BrokenCopy copy("traversal.glsl", "? min(r.occluders / r.texels, 1.0) : 0.0", "? 0.5 * r.occluders / r.texels : 0.0");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(fast_pcss(), copy.root(), pn::test::kQuick);  // one scene shows it
  size_t fast_failing = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, ": poisson") || named(r, ": exact") || named(r, ": hqepcss")) CHECK(r.comparison.pass);
    else if (named(r, "vs the staged passes") || named(r, "brute force")) fast_failing += r.comparison.pass ? 0 : 1;
  }
  // The quick run's scene (the tall blocker): eight fast settings vs the staged passes (six, and two with
  // area-weighted edges); all off, without and with the plane and with area-weighted edges, in both stages vs the CPU.
  CHECK(fast_failing == 8 + 2 * 3);
  CHECK(pn::test::failing_cases(results) == fast_failing);  // the fragment shader still equals the compute pass
}

TEST_CASE("negative: a shipped walk that ignores the work budget fails against the staged passes, the rest passes") {
  // Issue 52 (fast_pcss.h): the leaves' divisor dropped (leaves of leafSide at every width), and
  // every quad leaf of side 8 or more sampled 16 times — two mistakes in one copy (the suite's time),
  // each failing its own setting: the budget binding at leaf 2, and the shipped defaults.
  const pn::test::BrokenCopy copy(
      "fast_pcss.glsl",
      {{"pnTraversalLeafSide(leafSide, s.leafDivisor, size)", "pnTraversalLeafSide(leafSide, 0, size)"},
       {"pn_traversalSampleSide(s.leafMode, 1 << leafLevel)", "pn_traversalSampleSide(PN_LEAF_SAMPLED, 1 << leafLevel)"}});
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(fast_pcss(), copy.root(), pn::test::kQuick);
  for (const auto& r : results)
    if (!r.comparison.pass) INFO(r.name << ": " << r.comparison.where(r.tolerance));
  CHECK(pn::test::failing_named(results, ": fast: one call in a compute pass vs the staged passes") == 1);
  CHECK(pn::test::failing_named(results, "(the work budget binding): one call in a compute pass vs the staged") == 1);
  // Their counts too: the shipped defaults' Step 5 nodes and fetches (its blocker squares are under
  // 16 · 12 texels, where the divisor is no bound), and all three at leaf 2 with the divisor of 4.
  CHECK(pn::test::failing_named(results, ": fast: occlusionNodes vs their definition") == 1);
  CHECK(pn::test::failing_named(results, ": fast: fetches") == 1);
  CHECK(pn::test::failing_named(results, "(the work budget binding): blockerNodes vs their definition") == 1);
  CHECK(pn::test::failing_cases(results) == 7);
}

TEST_CASE("negative: a fragment shader that reads the pixel half a texel off fails only against the compute pass") {
  const pn::test::BrokenCopy copy("passes/pcss_one_call.frag", "pnOneCallShade(ivec2(gl_FragCoord.xy), fetches)",
                                  "pnOneCallShade(ivec2(gl_FragCoord.xy + vec2(0.5, 0.0)), fetches)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(fast_pcss(), copy.root(), pn::test::kQuick);
  size_t fragment_failing = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "vs the staged passes")) CHECK(r.comparison.pass);
    if (named(r, "fragment shader vs the compute pass")) fragment_failing += r.comparison.pass ? 0 : 1;
  }
  CHECK(fragment_failing == 21);  // every setting, with a plane or not, on the quick run's scene
}
