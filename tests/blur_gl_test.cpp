// The blur module on a real GL context against the direct 2-D convolution.
#include <catch2/catch.hpp>

#include <filesystem>

#include "check/module_check.h"
#include "core/error.h"
#include "gl/texture.h"
#include "pass_runners/blur_pass.h"
#include "broken_copy.h"
#include "driver_bundle.h"
#include "gl_test_context.h"
#include "fixture_images/texture_fixture.h"
#include "shader/flatten.h"
#include "shader/target.h"

namespace fs = std::filesystem;

namespace {

std::vector<pn::CaseResult> blur_cases(const fs::path& root, const pn::CheckOptions& options = {}) {
  const pn::SourceTree tree(root);
  return pn::find_module_check("blur").run({pn::test::gl_context(), tree, options});
}

}  // namespace

TEST_CASE("blur pass equals its reference on every fixture, size and parameter set, adaptive radius included", "[backend]") {
  const auto results = blur_cases(PENUMBRA_GLSL_DIR);
  // 6 fixed-radius sets, 5 adaptive ones with a radius-0 case each; 2 sets on 2 and 4 channels, a case a channel.
  REQUIRE(results.size() == (6 + 2 * 5 + 2 * (2 + 4)) * std::size(pn::fixtures::kTextureFixtures) *
                                std::size(pn::fixtures::kCheckSizes));
  pn::test::check_all_pass(results);
}

TEST_CASE("adaptive blur with user parameters (r 5, sigma 2, depth-aware, k 1.5) equals its reference") {
  pn::CheckOptions options;
  pn::BlurParams params{5, 2.0, true, 0.05};
  params.adaptive = true;
  params.pixels_per_texel = 1.5f;
  options.blur = params;
  pn::test::check_all_pass(blur_cases(PENUMBRA_GLSL_DIR, options));
}

TEST_CASE("negative: the adaptive radius without a filter map is refused with pn::Error") {
  const auto& context = pn::test::gl_context();
  const pn::SourceTree tree(PENUMBRA_GLSL_DIR);
  const pn::BlurPass pass(context, tree);
  const std::unique_ptr<pn::DeviceTexture> source = context.upload(pn::Image(4, 4));
  pn::BlurParams params;
  params.adaptive = true;
  CHECK_THROWS_AS(pass.run(*source, nullptr, 4, 4, params), pn::Error);
  CHECK_THROWS_WITH(pass.run(*source, nullptr, 4, 4, params), Catch::Contains("needs the filter-region map"));
}

TEST_CASE("blur with user parameters (r 5, sigma 2.5) equals the 2-D convolution") {
  pn::CheckOptions options;
  options.blur = pn::BlurParams{5, 2.5, false, 0.0};
  pn::test::check_all_pass(blur_cases(PENUMBRA_GLSL_DIR, options));
}

TEST_CASE("negative: a copy of blur.glsl with wrong weights from tap 2 on fails with where / expected / observed") {
  // The recurrence's ratio 10 % too large: w_1 stays right, w_2 (both sides) and beyond are off.
  const pn::test::BrokenCopy copy("blur.glsl", "g.ratio *= g.ratioStep;", "g.ratio *= 1.1 * g.ratioStep;");
  REQUIRE(copy.found());
  const auto results = blur_cases(copy.root());
  size_t named = 0;
  for (const auto& r : results) {
    // Cases where the taps 2 texels away exist and matter must fail, adaptive and depth-aware ones too.
    if (r.name == "noise 64x64 r=3 sigma=1" || r.name == "impulse 17x9 r=7 sigma=3" ||
        r.name == "noise 64x64 r=3 sigma=1 adaptive(k 1)" ||
        r.name == "noise 100x37 r=3 sigma=1 depth-aware(step_edge, tol 0.050000) adaptive(k 1)") {
      ++named;
      CHECK_FALSE(r.comparison.pass);
    }
  }
  CHECK(named == 4);
  CHECK(pn::test::failing_cases(results) > 0);
}

TEST_CASE("negative: a copy of blur.glsl whose adaptive radius is the whole penumbra fails the adaptive cases only") {
  const pn::test::BrokenCopy copy("blur.glsl", "float halfWidth = 0.5 * filterSide * pixelsPerTexel;",
                                  "float halfWidth = filterSide * pixelsPerTexel;");
  REQUIRE(copy.found());
  const auto results = blur_cases(copy.root());
  CHECK(pn::test::failing_named(results, "noise 64x64 r=3 sigma=1 adaptive(k 1)") > 0);
  CHECK(pn::test::failing_named(results, "radius 0 unchanged") > 0);  // contact pixels blurred
  size_t fixed_failing = 0;
  for (const auto& r : results)
    if (!r.comparison.pass && !pn::test::named(r, "adaptive")) ++fixed_failing;
  CHECK(fixed_failing == 0);
}

TEST_CASE("negative: a copy of blur.glsl that sanitises only the first channel fails the NaN/Inf channels beyond it, no other case") {
  const pn::test::BrokenCopy copy("blur.glsl", "return mix(v, vec4(float(PN_BLUR_NONFINITE_VALUE)), bad);",
                                  "return mix(v, vec4(float(PN_BLUR_NONFINITE_VALUE)), bvec4(bad.x, false, false, false));");
  REQUIRE(copy.found());
  const auto results = blur_cases(copy.root());
  size_t later_nonfinite = 0;
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    const bool nonfinite_later = r.name.rfind("nonfinite ", 0) == 0 && r.name.find(" channel 0 of") == std::string::npos &&
                                 r.name.find(" channel ") != std::string::npos;
    if (!nonfinite_later) CHECK(r.comparison.pass);
    else if (!r.comparison.pass) ++later_nonfinite;  // a small image may hold no non-finite texel
  }
  CHECK(later_nonfinite >= 4);  // 64x64 and 100x37 at least, 2 and 4 channels
}

TEST_CASE("the bundle of blur.glsl, #line markers and all, compiles with the GL driver", "[backend]") {
  for (const char* module : {"blur.glsl", "passes/blur.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}

TEST_CASE("negative: GL errors surface as pn::Error naming the operation", "[backend]") {
  const auto& context = pn::test::gl_context();
  context.gl().BindTexture(0x1234, 0);  // not a texture target: GL_INVALID_ENUM
  CHECK_THROWS_WITH(context.throw_if_gl_error("binding a bogus target"),
                    Catch::StartsWith("binding a bogus target: OpenGL error"));
  CHECK_NOTHROW(context.throw_if_gl_error("nothing pending"));
}

TEST_CASE("negative: a texture beyond GL_MAX_TEXTURE_SIZE or of zero size is refused before GL sees it", "[backend]") {
  const auto& context = pn::test::gl_context();
  GLint max_size = 0;
  context.gl().GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  CHECK_THROWS_WITH(pn::make_float_texture(context, max_size + 1, 4, 1), Catch::Contains("GL_MAX_TEXTURE_SIZE"));
  CHECK_THROWS_WITH(pn::make_float_texture(context, 0, 0, 1), Catch::Contains("texture size 0x0"));
}
