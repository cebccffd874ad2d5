// region on a real GL context against its CPU reference, and a copy with one
// deliberate mistake that the check must catch.
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/module_check.h"

using pn::test::BrokenCopy;
using pn::test::check_all_pass;
using pn::test::failing_cases;
using pn::test::run_check;

// The library's own run of the check is cli_check_all_gl's (every case must pass); this copy holds
// the case count too.
TEST_CASE("negative: a region copy that drops the cap in Step 5 fails, inside-the-map property included") {
  const BrokenCopy copy("region.glsl", "return ivec3(l, t, min(sp, cap));", "return ivec3(l, t, sp);");
  REQUIRE(copy.found());
  const auto results = run_check(pn::find_module_check("region"), copy.root());
  CHECK(results.size() == 30);  // 28 windows, 2 area-weighted (issue 54)
  CHECK(failing_cases(results) > 0);
  bool property_failed = false;
  for (const auto& r : results)
    if (r.name.find("inside the map") != std::string::npos && !r.comparison.pass) property_failed = true;
  CHECK(property_failed);
}
