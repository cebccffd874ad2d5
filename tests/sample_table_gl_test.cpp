// sample_table (the table's selection and scaling, and the stateless
// correlated multi-jitter option) on a real GL context, and copies with the
// mistakes the sample_table check exists to catch.
#include <catch2/catch.hpp>

#include "broken_copy.h"

using pn::test::BrokenCopy;
using pn::test::check_all_pass;
using pn::test::failing_cases;
using pn::test::run_check;

TEST_CASE("sample_table: strata, selection and scaling equal the paper's arithmetic") {
  check_all_pass(run_check(pn::find_module_check("sample_table"), PENUMBRA_GLSL_DIR));
}

TEST_CASE("negative: a sample table selection with the wrong set rule fails the sample_table check") {
  const BrokenCopy copy("sample_table.glsl", "return (pixel.x + pixel.y) & (PN_SAMPLE_TABLE_SETS - 1);",
                        "return (pixel.x * pixel.y) & (PN_SAMPLE_TABLE_SETS - 1);");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("sample_table"), copy.root())) > 0);
}

TEST_CASE("negative: a stateless generator that forgets to scale the sub-stratum fails the sample_table check") {
  const BrokenCopy copy("correlated_multi_jitter.glsl", "(float(column) + (float(sy) + jx) / float(un)) / float(um)",
                        "(float(column) + (float(sy) + jx)) / float(um)");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("sample_table"), copy.root())) > 0);
}
