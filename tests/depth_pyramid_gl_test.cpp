// depth_pyramid on a real GL context against its CPU reference, and a copy
// with one deliberate mistake that the check must catch.
#include <catch2/catch.hpp>

#include "broken_copy.h"
#include "check/module_check.h"
#include "gl/texture.h"
#include "gl_test_context.h"
#include "pass_runners/depth_pyramid_pass.h"

using pn::test::BrokenCopy;
using pn::test::check_all_pass;
using pn::test::failing_cases;
using pn::test::run_check;

// The library's own run of the check is cli_check_all_gl's (every case must pass); this copy holds
// the case count too.
TEST_CASE("negative: a depth_pyramid copy with a wrong child offset fails the depth_pyramid check") {
  const BrokenCopy copy("depth_pyramid.glsl", "origin + ivec2(h, 0)", "origin + ivec2(h - 1, 0)");
  REQUIRE(copy.found());
  const auto results = run_check(pn::find_module_check("depth_pyramid"), copy.root());
  CHECK(results.size() > 500);
  CHECK(failing_cases(results) > 0);
}

TEST_CASE("depth_pyramid: a maximum level beyond floor(log2 N) is clamped; non-square maps are refused before any GL work") {
  const auto& context = pn::test::gl_context();
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::DepthPyramidBuilder builder(context, tree);
  const std::unique_ptr<pn::DeviceTexture> uploaded = context.upload(pn::Image(64, 64, 1));
  const pn::DeviceTexture& map = *uploaded;
  CHECK(builder.build(map, 64, 64, 99).levels == 7);
  CHECK(builder.build(map, 64, 64, 3).levels == 4);
  CHECK_THROWS_WITH(builder.build(map, 64, 32, 99), "shadow map 64x32: expected a square map (N x N)");
}
