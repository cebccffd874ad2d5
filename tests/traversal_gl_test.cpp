// traversal on a real GL context, and copies with the mistakes the traversal
// check exists to catch.
#include <catch2/catch.hpp>

#include "broken_copy.h"

using pn::test::BrokenCopy;
using pn::test::check_all_pass;
using pn::test::failing_cases;
using pn::test::run_check;

TEST_CASE("traversal: exact at leaf 1, sampled and min leaves and budgets equal the CPU recursion") {
  const auto results = run_check(pn::find_module_check("traversal"), PENUMBRA_GLSL_DIR);
  REQUIRE(results.size() > 150);
  check_all_pass(results);
}

TEST_CASE("negative: a traversal that counts a texel at exactly dP - bias as occluding fails the exact check") {
  const BrokenCopy copy("traversal.glsl", "if (node.y < t.x) {", "if (node.y <= t.x) {");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("traversal"), copy.root())) > 0);
}

TEST_CASE("negative: a traversal that drops a child fails the exact check") {
  const BrokenCopy copy("traversal.glsl",
                        "pnTraversalVisitLeaf(r, pyramid, sampleTable, level - 1, origin + ivec2(h, h), t, leafMode, pixel);",
                        "");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("traversal"), copy.root())) > 0);
}
