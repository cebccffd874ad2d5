// PassBindings on a real GL context: what it binds is bound while it lives and
// unbound when it goes (bound_resources sees both), and a pass cannot start
// while an earlier one left something bound.
#include <catch2/catch.hpp>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/texture.h"
#include "gl_test_context.h"

using pn::test::gl_context;

TEST_CASE("pass bindings: a texture, an image and a uniform block are bound while they live and unbound after", "[backend]") {
  const pn::Context& context = gl_context();
  REQUIRE(pn::bound_resources(context).empty());
  const pn::GlObject texture = pn::make_float_texture(context, 4, 4, 1);
  const pn::GlObject target = pn::make_float_texture(context, 4, 4, 4);
  {
    pn::PassBindings bind(context);
    bind.texture(3, texture);
    bind.image(2, target, GL_WRITE_ONLY, GL_RGBA32F);
    const float block[4] = {1, 2, 3, 4};
    bind.uniform_data(7, block, sizeof block);
    CHECK(pn::bound_resources(context) ==
          std::vector<std::string>{"texture unit 3 (2D)", "image unit 2", "uniform buffer 7"});
  }
  CHECK(pn::bound_resources(context).empty());
}

TEST_CASE("negative: a pass cannot start while an earlier one left a texture bound", "[backend]") {
  const pn::Context& context = gl_context();
  const pn::GlObject texture = pn::make_float_texture(context, 4, 4, 1);
  context.gl().ActiveTexture(GL_TEXTURE5);  // a pass that bound by hand and left it
  context.gl().BindTexture(GL_TEXTURE_2D, texture.id());
  CHECK_THROWS_WITH(pn::PassBindings(context), Catch::StartsWith("a pass starts with texture unit 5 (2D) still bound"));
  context.gl().BindTexture(GL_TEXTURE_2D, 0);
  context.gl().ActiveTexture(GL_TEXTURE0);
  CHECK(pn::bound_resources(context).empty());
}
