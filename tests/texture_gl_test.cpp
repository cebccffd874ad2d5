// The texture fallbacks of gl/texture.h on whatever context the binary runs on (GL 4.5 core, or
// ES 3.1 with --api es310): a readback returns the uploaded bits, NaN and infinities included,
// through glGetTextureSubImage and through a framebuffer alike; a copied layer equals the
// layer and its view; a framebuffer clear zeroes every texel. Tagged [fallback] for the ES run.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "fixture_images/texture_fixture.h"
#include "gl/pass_bindings.h"
#include "gl/texture.h"
#include "gl_test_context.h"

using pn::test::gl_context;

namespace {

// Seeded noise with NaN, ±infinity and -0 in fixed places: what a readback must keep bit for bit.
pn::Image special_values(int width, int height, int channels) {
  const pn::Image noise = pn::generate_fixture(pn::find_fixture("noise"), width, height);
  pn::Image image(width, height, channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c) image.at(x, y, c) = noise.at(x, y) * static_cast<float>(c + 1) - 0.5f;
  image.at(0, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  image.at(1, 0, 0) = std::numeric_limits<float>::infinity();
  image.at(0, 1, channels - 1) = -std::numeric_limits<float>::infinity();
  image.at(1, 1, 0) = -0.0f;
  return image;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("texture readback: R32F, RG32F and RGBA32F 13x7 read back bit for bit, NaN and infinities included",
          "[backend][fallback]") {
  const pn::Context& context = gl_context();
  for (int channels : {1, 2, 4}) {
    CAPTURE(channels);
    const pn::Image image = special_values(13, 7, channels);
    const pn::FloatTexture texture = pn::upload_float_texture(context, image);
    CHECK(same_bits(pn::read_float_texture(context, texture).texels, image.texels));
    // The ES path, on any context: 4 floats a texel through a framebuffer.
    std::vector<float> rgba(13 * 7 * 4);
    pn::read_texels_via_framebuffer(context, texture, 0, 0, 13, 7, false, rgba.data());
    std::vector<float> first(13 * 7 * static_cast<size_t>(channels));
    for (size_t i = 0; i < 13 * 7; ++i)
      for (int c = 0; c < channels; ++c) first[i * channels + c] = rgba[i * 4 + c];
    CHECK(same_bits(first, image.texels));
  }
}

TEST_CASE("texture readback: an RGBA32UI texture reads back its uints, an array layer and a mip level their texels",
          "[backend][fallback]") {
  const pn::Context& context = gl_context();
  const pn::GlObject uints = pn::make_texture(context, GL_TEXTURE_2D, GL_RGBA32UI, 5, 3);
  std::vector<std::uint32_t> want(5 * 3 * 4);
  for (size_t i = 0; i < want.size(); ++i) want[i] = 0xFFFFFFF0u - static_cast<std::uint32_t>(i) * 0x01010101u;
  context.gl().ActiveTexture(GL_TEXTURE0);
  context.gl().BindTexture(GL_TEXTURE_2D, uints.id());
  context.gl().TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 5, 3, GL_RGBA_INTEGER, GL_UNSIGNED_INT, want.data());
  context.gl().BindTexture(GL_TEXTURE_2D, 0);
  context.throw_if_gl_error("uploading uints");
  CHECK(pn::read_uint4_texture(context, uints, 5, 3) == want);

  // A 3-layer array, layer 2 written; a 2-level texture, level 1 written.
  const pn::Image layer = special_values(6, 6, 4);
  const pn::GlObject array = pn::make_float_texture_array(context, 6, 6, 3, 4);
  context.gl().BindTexture(GL_TEXTURE_2D_ARRAY, array.id());
  context.gl().TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 2, 6, 6, 1, GL_RGBA, GL_FLOAT, layer.texels.data());
  context.gl().BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  const pn::Image level = special_values(4, 2, 4);
  const pn::GlObject mips = pn::make_texture(context, GL_TEXTURE_2D, GL_RGBA32F, 8, 4, 1, 2);
  context.gl().BindTexture(GL_TEXTURE_2D, mips.id());
  context.gl().TexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 4, 2, GL_RGBA, GL_FLOAT, level.texels.data());
  context.gl().BindTexture(GL_TEXTURE_2D, 0);
  context.throw_if_gl_error("uploading a layer and a level");
  CHECK(same_bits(pn::read_float_texture_layer(context, array, 2, 6, 6, 4).texels, layer.texels));
  CHECK(same_bits(pn::read_float_texture_layer(context, mips, 0, 4, 2, 4, 1).texels, level.texels));
  CHECK(pn::bound_resources(context).empty());
}

TEST_CASE("texture layers: a copied layer equals the layer and its view; a framebuffer clear zeroes 9x5 RGBA32F",
          "[backend][fallback]") {
  const pn::Context& context = gl_context();
  const pn::Image layer = special_values(9, 9, 4);
  const pn::GlObject array = pn::make_float_texture_array(context, 9, 9, 2, 4);
  context.gl().BindTexture(GL_TEXTURE_2D_ARRAY, array.id());
  context.gl().TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 1, 9, 9, 1, GL_RGBA, GL_FLOAT, layer.texels.data());
  context.gl().BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  const pn::GlObject copy = pn::copy_texture_layer(context, array, 1, 9, 9, 4);
  CHECK(same_bits(pn::read_float_texture(context, copy, 9, 9, 4).texels, layer.texels));
  if (context.has_texture_views()) {
    const pn::GlObject view = pn::make_texture_view_layer(context, array, 1, 4);
    CHECK(same_bits(pn::read_float_texture(context, view, 9, 9, 4).texels, layer.texels));
  }

  const pn::FloatTexture cleared = pn::upload_float_texture(context, special_values(9, 5, 4));
  const float zero[4] = {0, 0, 0, 0};
  pn::clear_float_texture(context, cleared, zero);
  CHECK(same_bits(pn::read_float_texture(context, cleared).texels, pn::Image(9, 5, 4).texels));
  CHECK(pn::bound_resources(context).empty());
}
