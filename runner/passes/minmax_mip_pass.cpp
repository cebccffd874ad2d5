#include "passes/minmax_mip_pass.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "reference/depth_pyramid_reference.h"

namespace pn::glsl {
#include "passes/minmax_mip_build.h"
PN_STD140_SIZE(PnMipBuildParams, 16);
}  // namespace pn::glsl

namespace pn {

int MinMaxMipChain::padded_size_for(int map_size) {
  int p = 2;  // two nodes a texel: level 0 at least one texel wide
  while (p < map_size && p < (1 << 30)) p *= 2;
  return p;
}

std::size_t MinMaxMipChain::memory_bytes(int map_size) {
  std::size_t texels = 0;
  for (int side = padded_size_for(map_size); side >= 1; side /= 2)
    texels += static_cast<std::size_t>(std::max(side / 2, 1)) * side;
  return 16 * texels;  // RGBA32F texels, two nodes each
}

MinMaxMipBuilder::MinMaxMipBuilder(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/minmax_mip_build.comp")) {}

MinMaxMipChain MinMaxMipBuilder::allocate(int map_size) const {
  const auto& gl = context_->gl();
  GLint max_size = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  const int padded = MinMaxMipChain::padded_size_for(map_size);
  if (map_size < 1 || padded > max_size)
    throw Error("min/max mip chain of a " + std::to_string(map_size) + "² map: expected 1 <= N and its power of two <= " +
                std::to_string(max_size) + " (GL_MAX_TEXTURE_SIZE)");
  MinMaxMipChain chain;
  chain.map_size = map_size;
  chain.padded_size = padded;
  chain.levels = floor_log2(padded) + 1;
  chain.texture = make_texture(*context_, GL_TEXTURE_2D, GL_RGBA32F, padded / 2, padded, 1, chain.levels);
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
    const int rows = chain.padded_size >> level;
    program_.dispatch(std::max(rows / 2, 1), rows);
  }
}

MinMaxMipChain MinMaxMipBuilder::build(const GlObject& shadow_map, int map_size) const {
  MinMaxMipChain chain = allocate(map_size);
  build_into(shadow_map, chain);
  return chain;
}

}  // namespace pn
