#include "passes/reuse_pass.h"

#include <cstdint>

#include "gl/texture.h"

namespace pn {

ReusePass::ReusePass(const Context& context, const SourceTree& tree)
    : context_(&context),
      link_(compile_pass(context, tree, "passes/reuse_link.comp")),
      gather_(compile_pass(context, tree, "passes/reuse_gather.comp")) {}

GlObject ReusePass::link(const GlObject& entries, int width, int height, const ReuseParams& params) const {
  params.validate();
  // std140 block PnReuseParams.
  const struct {
    float sigma1, sigma2, sigma3;
    std::int32_t tile;
  } block{params.sigma1, params.sigma2, params.sigma3, params.tile};
  GlObject parents = make_float_texture(*context_, width, height, 1);
  GlObject ubo = bind_uniform_buffer(*context_, 3, &block, sizeof block);
  context_->gl().BindTextureUnit(0, entries.id());
  context_->gl().BindImageTexture(2, parents.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  link_.dispatch(width, height);
  return parents;
}

GlObject ReusePass::gather(const GlObject& parents, const GlObject& values, int width, int height, int tile) const {
  const std::int32_t block[4] = {tile, 0, 0, 0};  // std140 block PnReuseGatherParams
  GlObject gathered = make_float_texture(*context_, width, height, 4);
  GlObject ubo = bind_uniform_buffer(*context_, 3, block, sizeof block);
  context_->gl().BindTextureUnit(0, parents.id());
  context_->gl().BindTextureUnit(1, values.id());
  context_->gl().BindImageTexture(2, gathered.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gather_.dispatch(width, height);
  return gathered;
}

}  // namespace pn
