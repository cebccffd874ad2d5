// traversal on a real GL context, and copies with the mistakes the traversal
// check exists to catch.
#include <catch2/catch.hpp>

#include "broken_copy.h"

using pn::test::BrokenCopy;
using pn::test::failing_cases;
using pn::test::run_check;

TEST_CASE("negative: a traversal that counts a texel at exactly dP - bias as occluding fails the exact check") {
  const BrokenCopy copy("traversal_pyramid.glsl", "if (node.y < t.x) {", "if (node.y <= t.x) {");
  REQUIRE(copy.found());
  // The library's run is cli_check_all_gl's (it must pass); the copy's quick run holds the case count.
  const auto results = run_check(pn::find_module_check("traversal"), copy.root(), pn::test::kQuick);
  CHECK(results.size() > 150);
  CHECK(failing_cases(results) > 0);
}

TEST_CASE("negative: a traversal that drops a child fails the exact check") {
  const BrokenCopy copy("traversal_pyramid.glsl",
                        "pn_traversalVisitLeaf(r, pyramid, sampleTable, area, level - 1, origin + ivec2(h, h), t, leafMode, pixel);",
                        "");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("traversal"), copy.root(), pn::test::kQuick)) > 0);
}

TEST_CASE("negative: quad leaves sampled as the paper's (16 samples from side 8) fail the quad cases only") {
  // Issue 52 (traversal.h's PN_LEAF_QUAD): the 4-sample group's cap dropped.
  const BrokenCopy copy("traversal.glsl", "return leafMode == PN_LEAF_QUAD ? min(side, 4) : side;", "return side;");
  REQUIRE(copy.found());
  const auto results = run_check(pn::find_module_check("traversal"), copy.root(), pn::test::kQuick);
  CHECK(pn::test::failing_named(results, " quad ") > 0);
  CHECK(failing_cases(results) == pn::test::failing_named(results, " quad "));
}
