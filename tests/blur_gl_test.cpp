// The blur module on a real GL context against the direct 2-D convolution.
#include <catch2/catch.hpp>

#include <filesystem>

#include "check/module_check.h"
#include "core/error.h"
#include "gl/texture.h"
#include "broken_copy.h"
#include "driver_bundle.h"
#include "gl_test_context.h"
#include "fixture/texture_fixture.h"
#include "shader/flatten.h"
#include "shader/target.h"

namespace fs = std::filesystem;

namespace {

std::vector<pn::CaseResult> blur_cases(const fs::path& root, const pn::CheckOptions& options = {}) {
  const pn::SourceTree tree(root);
  return pn::run_blur_check({pn::test::gl_context(), tree, options});
}

}  // namespace

TEST_CASE("blur pass equals the direct 2-D convolution on every fixture, size and parameter set") {
  const auto results = blur_cases(PENUMBRA_GLSL_DIR);
  REQUIRE(results.size() == 6 * std::size(pn::fixtures::kTextureFixtures) * std::size(pn::fixtures::kCheckSizes));
  pn::test::check_all_pass(results);
}

TEST_CASE("blur with user parameters (r 5, sigma 2.5) equals the 2-D convolution") {
  pn::CheckOptions options;
  options.blur = pn::BlurParams{5, 2.5, false, 0.0};
  pn::test::check_all_pass(blur_cases(PENUMBRA_GLSL_DIR, options));
}

TEST_CASE("negative: a copy of blur.glsl with one wrong weight fails with where / expected / observed") {
  // Break only the tap two texels to the right.
  const pn::test::BrokenCopy copy(
      "blur.glsl", "float w = (r == 0) ? 1.0 : pnBlurGaussian(i, sigma);",
      "float w = (r == 0) ? 1.0 : pnBlurGaussian(i, sigma) * (i == 2 ? 1.5 : 1.0);");
  REQUIRE(copy.found());
  const auto results = blur_cases(copy.root());
  size_t named = 0;
  for (const auto& r : results) {
    // Cases where the tap 2 texels away exists and matters must fail.
    if (r.name == "noise 64x64 r=3 sigma=1" || r.name == "impulse 17x9 r=7 sigma=3") {
      ++named;
      CHECK_FALSE(r.comparison.pass);
    }
  }
  CHECK(named == 2);
  CHECK(pn::test::failing_cases(results) > 0);
}

TEST_CASE("the bundle of blur.glsl, #line markers and all, compiles with the GL driver") {
  for (const char* module : {"blur.glsl", "passes/blur.comp"}) {
    INFO(module);
    CHECK(pn::test::driver_compiles_bundle(module));
  }
}

TEST_CASE("negative: GL errors surface as pn::Error naming the operation") {
  const auto& context = pn::test::gl_context();
  context.gl().BindTexture(0x1234, 0);  // not a texture target: GL_INVALID_ENUM
  CHECK_THROWS_WITH(context.throw_if_gl_error("binding a bogus target"),
                    Catch::StartsWith("binding a bogus target: OpenGL error"));
  CHECK_NOTHROW(context.throw_if_gl_error("nothing pending"));
}

TEST_CASE("negative: a texture beyond GL_MAX_TEXTURE_SIZE or of zero size is refused before GL sees it") {
  const auto& context = pn::test::gl_context();
  GLint max_size = 0;
  context.gl().GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  CHECK_THROWS_WITH(pn::make_float_texture(context, max_size + 1, 4, 1), Catch::Contains("GL_MAX_TEXTURE_SIZE"));
  CHECK_THROWS_WITH(pn::make_float_texture(context, 0, 0, 1), Catch::Contains("texture size 0x0"));
}
