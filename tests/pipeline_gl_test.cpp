// The pipeline on a real GL context, with a deliberate mistake: Step 6 must
// cut its blur at the G-buffer's depth edges and at pixels without a surface.
#include <catch2/catch.hpp>

#include "broken_copy.h"
#include "check/module_check.h"

using pn::test::BrokenCopy;
using pn::test::failing_named;
using pn::test::run_check;

TEST_CASE("negative: a Step 3 that gives every receiver one depth blurs across depth edges and into the sky; "
          "the pipeline check fails there") {
  const BrokenCopy copy("passes/pcss_search.comp", "vec4(surface ? receiver.z : pn_pyramidFar(), 0.0, 0.0, 0.0)",
                        "vec4(1.0, 0.0, 0.0, 0.0)");
  REQUIRE(copy.found());
  const auto results = run_check(pn::find_module_check("pipeline"), copy.root(), pn::test::kQuick);  // one scene shows it
  CHECK(failing_named(results, "Step 6 vs the depth-aware blur") > 0);
  CHECK(failing_named(results, "pixels that see no surface stay lit") > 0);
}
