#include "passes/blur_pass.h"

#include <cstdint>
#include <string>

#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/blur.h"
PN_STD140_SIZE(PnBlurPassParams, 32);
PN_STD140_OFFSET(PnBlurPassParams, radius, 8);
PN_STD140_OFFSET(PnBlurPassParams, depthTolerance, 20);
}  // namespace pn::glsl

namespace pn {

BlurPass::BlurPass(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/blur.comp")) {}  // limits: glsl/blur.h, as the reference

GlObject BlurPass::run(const GlObject& source, const GlObject* depth, int width, int height,
                       const BlurParams& params) const {
  params.validate();
  GlObject temporary = make_float_texture(*context_, width, height, 1);
  GlObject target = make_float_texture(*context_, width, height, 1);

  auto one_pass = [&](const GlObject& in, const GlObject& out, int ax, int ay) {
    const glsl::PnBlurPassParams block{{ax, ay}, params.radius, static_cast<float>(params.sigma),
                                       params.depth_aware ? 1 : 0, static_cast<float>(params.depth_tolerance)};
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_BLUR_SOURCE_BINDING, in);
    bind.texture(PN_BLUR_DEPTH_BINDING, depth != nullptr ? *depth : source);
    bind.image(PN_BLUR_TARGET_BINDING, out, GL_WRITE_ONLY, GL_R32F);
    program_.dispatch(width, height);
  };
  one_pass(source, temporary, 1, 0);
  one_pass(temporary, target, 0, 1);
  return target;
}

}  // namespace pn
