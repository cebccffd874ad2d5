#include "passes/cascade_blend_pass.h"

#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/cascade_blend.h"
PN_STD140_SIZE(PnCascadeBlendParams, 32);
PN_STD140_OFFSET(PnCascadeBlendParams, near, 16);
PN_STD140_OFFSET(PnCascadeBlendParams, fadeLast, 28);
}  // namespace pn::glsl

namespace pn {

CascadeBlendPass::CascadeBlendPass(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/cascade_blend.comp")),
      unused_(make_float_texture(context, 1, 1, 1)) {}

FloatTexture CascadeBlendPass::run(const CascadeBlend& cascades, const std::vector<const GlObject*>& visibilities,
                                   int screen_size) const {
  const size_t count = visibilities.size();
  if (count < 1 || count > 4 || !cascades.view_depth)
    throw Error("cascade blend: " + std::to_string(count) +
                " visibilities: expected one a cascade, 1 ... 4, and the camera's view depth");
  glsl::PnCascadeBlendParams block{};
  block.splitFar = {cascades.split_far[0], cascades.split_far[1], cascades.split_far[2], cascades.split_far[3]};
  block.near = cascades.near;
  block.count = static_cast<int>(count);
  block.band = cascades.band;
  block.fadeLast = cascades.fade_last ? 1 : 0;
  FloatTexture target = make_float_texture(*context_, screen_size, screen_size, 1);
  {
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_CASCADE_BLEND_VIEW_DEPTH_BINDING, *cascades.view_depth);
    const int slots[4] = {PN_CASCADE_BLEND_VISIBILITY0_BINDING, PN_CASCADE_BLEND_VISIBILITY1_BINDING,
                          PN_CASCADE_BLEND_VISIBILITY2_BINDING, PN_CASCADE_BLEND_VISIBILITY3_BINDING};
    for (size_t c = 0; c < 4; ++c) bind.texture(slots[c], c < count ? *visibilities[c] : unused_);
    bind.image(PN_CASCADE_BLEND_TARGET_BINDING, target, GL_WRITE_ONLY, GL_R32F);
    program_.dispatch(screen_size, screen_size);
  }
  context_->throw_if_gl_error("cascade blend");
  return target;
}

}  // namespace pn
