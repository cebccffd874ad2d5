// depth_cache.glsl and the shadow-map caches on a real GL context: the check
// passes; broken copies of the module and a cache that does not dilate its
// dirty rectangles for the structures fail it.
#include <catch2/catch.hpp>

#include <string>

#include "broken_copy.h"
#include "check/depth_cache_check.h"
#include "check/module_check.h"
#include "fixture_images/texture_fixture.h"
#include "gl_test_context.h"

using pn::test::named;

namespace {

const pn::ModuleCheck& depth_cache() { return pn::find_module_check("depth_cache"); }

constexpr size_t kModuleCases = 2 * std::size(pn::fixtures::kTextureFixtures) + 1;  // + maps of unequal sizes
constexpr size_t kComposeCases = 3, kSequences = 3, kPerSequence = 4;
constexpr const char* kNonfinite = "nonfinite";

}  // namespace

TEST_CASE("negative: a copy of depth_cache.glsl that takes the max of the two maps fails every pair of different maps, "
          "the compose pass and the two-map cache's sequence (the dirty-rectangle cache composes by the depth test)") {
  const pn::test::BrokenCopy copy("depth_cache.glsl", "return min(pn_depthCacheSanitize(staticDepth)",
                                  "return max(pn_depthCacheSanitize(staticDepth)");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(depth_cache(), copy.root());
  const auto& fx = pn::fixtures::kTextureFixtures;
  size_t pairs = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    for (size_t i = 0; i < std::size(fx); ++i) {
      const std::string different = std::string("static ") + fx[i].name + ", dynamic " + fx[(i + 3) % std::size(fx)].name + " ";
      if (r.name.rfind(different, 0) == 0) {
        CHECK_FALSE(r.comparison.pass);
        ++pairs;
      }
      const std::string same = std::string("static ") + fx[i].name + ", dynamic " + fx[i].name + " ";
      if (r.name.rfind(same, 0) == 0 && !named(r, kNonfinite)) CHECK(r.comparison.pass);  // max(a, a) == min(a, a)
    }
    if (named(r, "compose pass") || (named(r, "two-map cache") && named(r, "composed map =="))) CHECK_FALSE(r.comparison.pass);
    if (named(r, "dirty-rect cache")) CHECK(r.comparison.pass);
  }
  CHECK(pairs == std::size(fx));
  CHECK(pn::test::failing_named(results, "composed map ==") == 1);
}

// The library's own run of the check is cli_check_all_gl's (every case must pass); this copy, which
// fails only where a map holds NaN or -Inf, also holds the case count and what the sequences did.
TEST_CASE("negative: a copy of depth_cache.glsl that forgets the non-finite rule fails where a map holds NaN or -Inf, only there") {
  const pn::test::BrokenCopy copy("depth_cache.glsl", "return (isnan(d) || isinf(d)) ? pnDepthCacheFar() : d;",
                                  "return d;");
  REQUIRE(copy.found());
  const auto results = pn::test::run_check(depth_cache(), copy.root());
  CHECK(results.size() == kModuleCases + kComposeCases + kSequences * kPerSequence);
  // The sequences did what the issue asks of them: objects start, stop, leave the map and cross.
  for (const auto& r : results)
    if (named(r, "K = 0.3")) {
      INFO(r.name);
      CHECK_FALSE(named(r, "(0 starts"));
      CHECK_FALSE(named(r, " 0 stops"));
      CHECK_FALSE(named(r, " 0 exits"));
      CHECK_FALSE(named(r, " 0 box-frames"));
    }
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "static ") && named(r, "[0] composed")) {
      if (named(r, kNonfinite)) CHECK_FALSE(r.comparison.pass);
      else CHECK(r.comparison.pass);
    }
    if (named(r, "cache, ")) CHECK(r.comparison.pass);  // rendered maps hold +Inf at most: min(+Inf, d) is d
  }
  CHECK(pn::test::failing_named(results, kNonfinite) >= 1);
}

TEST_CASE("negative: a dirty-rectangle cache that rounds its rectangles in for the structures keeps a map equal to the "
          "full render but a stale mip chain and pyramid") {
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::CheckOptions options;
  pn::MotionSequence sequence;
  sequence.source = "dirty-rect";
  sequence.k = 0.3;
  sequence.frames = 40;
  sequence.options.dilate_updates = false;
  const auto results = pn::run_motion_sequence({pn::test::gl_context(), tree, options}, sequence);
  REQUIRE(results.size() == kPerSequence);
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    if (named(r, "composed map ==")) CHECK(r.comparison.pass);
    if (named(r, "mip chain") || named(r, "pyramid kept")) CHECK_FALSE(r.comparison.pass);
  }
}
