// reuse and light_model on a real GL context, and copies with a mistake each.
#include <catch2/catch.hpp>

#include "broken_copy.h"

using pn::test::BrokenCopy;
using pn::test::check_all_pass;
using pn::test::failing_cases;
using pn::test::run_check;

TEST_CASE("reuse: parents, representatives and gathered values equal the CPU reference; no group crosses a tile") {
  check_all_pass(run_check(pn::find_module_check("reuse"), PENUMBRA_GLSL_DIR));
}

TEST_CASE("negative: reuse links that ignore the tile border fail, the tile property included") {
  const BrokenCopy copy("reuse.glsl", {{"if (p.x % tile != 0 && pnReuseSimilar", "if (p.x > 0 && pnReuseSimilar"},
                                       {"if (parent == PN_REUSE_LEFT && q.x % tile != 0)", "if (parent == PN_REUSE_LEFT)"}});
  REQUIRE(copy.found());
  const auto results = run_check(pn::find_module_check("reuse"), copy.root());
  CHECK(failing_cases(results) > 0);
  bool tile_failed = false;
  for (const auto& r : results)
    if (r.name.find("crosses a tile") != std::string::npos && !r.comparison.pass) tile_failed = true;
  CHECK(tile_failed);
}

TEST_CASE("light_model: the GLSL widths equal the C++ light model") {
  check_all_pass(run_check(pn::find_module_check("light_model"), PENUMBRA_GLSL_DIR));
}

TEST_CASE("negative: a penumbra divided by the receiver depth instead of the blocker's fails the light_model check") {
  const BrokenCopy copy("light_model.glsl", "(light.width / blockerDepth + light.spread)",
                        "(light.width / receiverDepth + light.spread)");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("light_model"), copy.root())) > 0);
}

TEST_CASE("negative: a penumbra without the directional light's spread fails the directional cases only") {
  const BrokenCopy copy("light_model.glsl", "(light.width / blockerDepth + light.spread)", "(light.width / blockerDepth)");
  REQUIRE(copy.found());
  const auto results = run_check(pn::find_module_check("light_model"), copy.root());
  size_t directional_failures = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (pn::test::named(r, "directional light")) directional_failures += r.comparison.pass ? 0 : 1;
    else CHECK(r.comparison.pass);
  }
  CHECK(directional_failures > 0);
}

TEST_CASE("shadow_map: each scene's shadow map and G-buffer equal their ray casts off silhouettes") {
  check_all_pass(run_check(pn::find_module_check("shadow_map"), PENUMBRA_GLSL_DIR));
}

TEST_CASE("negative: a shadow map of window depth instead of linear light depth fails the shadow_map check") {
  const BrokenCopy copy("passes/shadow_depth.frag", "pnDepth = vec4(pnLinearDepth, 0.0, 0.0, 0.0);",
                        "pnDepth = vec4(gl_FragCoord.z, 0.0, 0.0, 0.0);");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("shadow_map"), copy.root())) > 0);
}

TEST_CASE("negative: a G-buffer with the light depth's sign flipped fails the shadow_map check") {
  const BrokenCopy copy("light_model.glsl", "return vec3((clip.xy / clip.w * 0.5 + 0.5) * mapSize, -view.z);",
                        "return vec3((clip.xy / clip.w * 0.5 + 0.5) * mapSize, view.z);");
  REQUIRE(copy.found());
  CHECK(failing_cases(run_check(pn::find_module_check("shadow_map"), copy.root())) > 0);
}
