#include "passes/minmax_mip_pass.h"

#include <algorithm>

#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "reference/depth_pyramid_reference.h"

namespace pn::glsl {
#include "passes/minmax_mip_build.h"
PN_STD140_SIZE(PnMipBuildParams, 16);
}  // namespace pn::glsl

namespace pn {
namespace {

int level_size(int n, int level) { return std::max(1, (n + (1 << level) - 1) >> level); }

}  // namespace

std::size_t MinMaxMipChain::memory_bytes(int map_size) {
  std::size_t texels = 0;
  for (int level = 0; level <= floor_log2(map_size); ++level)
    texels += static_cast<std::size_t>(level_size(map_size, level)) * level_size(map_size, level);
  return 16 * texels;
}

MinMaxMipBuilder::MinMaxMipBuilder(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/minmax_mip_build.comp")) {}

MinMaxMipChain MinMaxMipBuilder::allocate(int map_size) const {
  MinMaxMipChain chain;
  chain.map_size = map_size;
  chain.levels = floor_log2(map_size) + 1;
  chain.texture = GlObject(*context_, GlKind::texture, GL_TEXTURE_2D);
  const auto& gl = context_->gl();
  gl.TextureStorage2D(chain.texture.id(), chain.levels, GL_RGBA32F, map_size, map_size);
  gl.TextureParameteri(chain.texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  gl.TextureParameteri(chain.texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  context_->throw_if_gl_error("allocating the min/max mip chain");
  return chain;
}

void MinMaxMipBuilder::build_into(const GlObject& shadow_map, const MinMaxMipChain& chain) const {
  for (int level = 0; level < chain.levels; ++level) {
    const glsl::PnMipBuildParams block{level};
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_MINMAX_MIP_SHADOW_MAP_BINDING, shadow_map);
    bind.texture(PN_MINMAX_MIP_READ_BINDING, chain.texture);
    bind.image(PN_MINMAX_MIP_WRITE_BINDING, chain.texture, GL_WRITE_ONLY, GL_RGBA32F, level);
    const int size = level_size(chain.map_size, level);
    program_.dispatch(size, size);
  }
}

}  // namespace pn
