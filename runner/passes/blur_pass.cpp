#include "passes/blur_pass.h"

#include <cstdint>
#include <string>

#include "gl/texture.h"

namespace pn {
namespace {

// Mirrors the std140 block PnBlurPassParams of passes/blur.comp.
struct BlurPassParams {
  std::int32_t axis[2];
  std::int32_t radius;
  float sigma;
  std::int32_t depth_aware;
  float depth_tolerance;
  std::int32_t padding[2];
};
static_assert(sizeof(BlurPassParams) == 32, "std140 layout of PnBlurPassParams");

}  // namespace

BlurPass::BlurPass(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/blur.comp",
                            {{"PN_BLUR_MAX_RADIUS", std::to_string(kBlurMaxRadius)},
                             {"PN_BLUR_NONFINITE_VALUE", std::to_string(kBlurNonfiniteValue)}})) {}

GlObject BlurPass::run(const GlObject& source, const GlObject* depth, int width, int height,
                       const BlurParams& params) const {
  params.validate();
  const auto& gl = context_->gl();
  GlObject temporary = make_float_texture(*context_, width, height, 1);
  GlObject target = make_float_texture(*context_, width, height, 1);
  const GLuint depth_id = depth != nullptr ? depth->id() : source.id();

  auto one_pass = [&](const GlObject& in, const GlObject& out, int ax, int ay) {
    const BlurPassParams block{{ax, ay}, params.radius, static_cast<float>(params.sigma),
                               params.depth_aware ? 1 : 0, static_cast<float>(params.depth_tolerance), {0, 0}};
    GlObject ubo = bind_uniform_buffer(*context_, 3, &block, sizeof block);
    gl.BindTextureUnit(0, in.id());
    gl.BindTextureUnit(1, depth_id);
    gl.BindImageTexture(2, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    program_.dispatch(width, height);
  };
  one_pass(source, temporary, 1, 0);
  one_pass(temporary, target, 0, 1);
  return target;
}

}  // namespace pn
