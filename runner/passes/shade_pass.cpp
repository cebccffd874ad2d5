#include "passes/shade_pass.h"

#include "passes/scene_draw.h"

namespace pn {

ShadePass::ShadePass(const Context& context, const SourceTree& tree, std::string stem, unsigned image_binding)
    : context_(&context), tree_(tree), stem_(std::move(stem)), image_binding_(image_binding),
      compute_(context, tree, stem_ + ".comp") {}

FloatTexture ShadePass::run(ShadeStage stage, const std::vector<Define>& defines, int size, PassBindings& bind,
                            int fragment_channels) const {
  if (stage == ShadeStage::compute) {
    FloatTexture out = make_float_texture(*context_, size, size, 1);
    bind.image(image_binding_, out, GL_WRITE_ONLY, GL_R32F);
    compute_.get(defines).dispatch(size, size);
    return out;
  }
  const std::string key = define_key(defines);
  auto found = fragment_.find(key);
  if (found == fragment_.end())
    found = fragment_.emplace(key, link_raster_pass(*context_, tree_, kFullScreenVertex, stem_ + ".frag", defines))
                .first;
  RasterTarget target(*context_, size, fragment_channels);
  target.draw_full_screen(found->second);
  return target.release_texture();
}

}  // namespace pn
