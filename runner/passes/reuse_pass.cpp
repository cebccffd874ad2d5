#include "passes/reuse_pass.h"

#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/reuse_gather.h"
#include "passes/reuse_link.h"
PN_STD140_SIZE(PnReuseParams, 16);
PN_STD140_OFFSET(PnReuseParams, sigma3, 8);
PN_STD140_OFFSET(PnReuseParams, tile, 12);
PN_STD140_SIZE(PnReuseGatherParams, 16);
}  // namespace pn::glsl

namespace pn {

ReusePass::ReusePass(const Context& context, const SourceTree& tree)
    : context_(&context),
      link_(compile_pass(context, tree, "passes/reuse_link.comp")),
      gather_(compile_pass(context, tree, "passes/reuse_gather.comp")) {}

FloatTexture ReusePass::link(const GlObject& entries, int width, int height, const ReuseParams& params) const {
  params.validate();
  FloatTexture parents = make_float_texture(*context_, width, height, 1);
  const glsl::PnReuseParams block{params.sigma1, params.sigma2, params.sigma3, params.tile};
  PassBindings bind(*context_);
  bind.uniform(block);
  bind.texture(PN_REUSE_LINK_ENTRIES_BINDING, entries);
  bind.image(PN_REUSE_LINK_PARENTS_BINDING, parents, GL_WRITE_ONLY, GL_R32F);
  link_.dispatch(width, height);
  return parents;
}

FloatTexture ReusePass::gather(const GlObject& parents, const GlObject& values, int width, int height, int tile) const {
  FloatTexture gathered = make_float_texture(*context_, width, height, 4);
  const glsl::PnReuseGatherParams block{tile};
  PassBindings bind(*context_);
  bind.uniform(block);
  bind.texture(PN_REUSE_GATHER_PARENTS_BINDING, parents);
  bind.texture(PN_REUSE_GATHER_VALUES_BINDING, values);
  bind.image(PN_REUSE_GATHER_RESULT_BINDING, gathered, GL_WRITE_ONLY, GL_RGBA32F);
  gather_.dispatch(width, height);
  return gathered;
}

}  // namespace pn
