#include "passes/minmax_mip_pass.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "modules/depth_pyramid.h"

namespace pn::glsl {
#include "passes/minmax_mip_build.h"
PN_STD140_SIZE(PnMipBuildParams, 16);
PN_STD140_OFFSET(PnMipBuildParams, texelCount, 8);
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

Image read_mip_chain_level(const Context& context, const MinMaxMipChain& chain, int level) {
  return read_float_texture_layer(context, chain.texture, 0, chain.level_width(level), chain.level_rows(level), 4, level);
}

MinMaxMipBuilder::MinMaxMipBuilder(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/minmax_mip_build.comp")),
      no_texels_(make_buffer(context, 2 * sizeof(int), nullptr)) {}

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

void MinMaxMipBuilder::dispatch_level(const GlObject& shadow_map, const MinMaxMipChain& chain, int level, TexelRun run,
                                      const GlObject& texels) const {
  if (!run.whole && run.count <= 0) return;
  const bool listed = run.count > 0 && !run.whole;
  const glsl::PnMipBuildParams block{level, run.first, listed ? run.count : 0};
  PassBindings bind(*context_);
  bind.uniform(block);
  bind.texture(PN_MINMAX_MIP_SHADOW_MAP_BINDING, shadow_map);
  bind.texture(PN_MINMAX_MIP_READ_BINDING, chain.texture);
  bind.image(PN_MINMAX_MIP_WRITE_BINDING, chain.texture, GL_WRITE_ONLY, GL_RGBA32F, level);
  bind.storage_buffer(PN_MINMAX_MIP_TEXELS_BINDING, listed ? texels : no_texels_);
  dispatch_texel_run(program_, run, chain.level_width(level), chain.level_rows(level));
}

void MinMaxMipBuilder::build_into(const GlObject& shadow_map, const MinMaxMipChain& chain) const {
  for (int level = 0; level < chain.levels; ++level) dispatch_level(shadow_map, chain, level, {0, 0, true}, no_texels_);
}

void MinMaxMipBuilder::update_into(const GlObject& shadow_map, const MinMaxMipChain& chain,
                                   const std::vector<TexelRect>& rects, TexelList& texels, bool round_out) const {
  texels.clear();
  std::vector<TexelRun> runs;
  std::vector<TexelRect> at_level;
  for (int level = 0; level < chain.levels; ++level) {
    at_level.clear();
    for (const TexelRect& r : rects) {
      if (r.empty()) continue;
      // Nodes [n0, n1) on each axis; two nodes a texel across.
      const auto end = [&](int e) { return round_out ? ((e - 1) >> level) + 1 : e >> level; };
      const int nx0 = r.x0 >> level, nx1 = end(r.x1), ny0 = r.y0 >> level, ny1 = end(r.y1);
      if (nx1 <= nx0 || ny1 <= ny0) continue;
      at_level.push_back({nx0 >> 1, ny0, ((nx1 - 1) >> 1) + 1, ny1});
    }
    runs.push_back(texels.add(at_level, chain.level_width(level), chain.level_rows(level)));
  }
  texels.upload(*context_);
  for (int level = 0; level < chain.levels; ++level)
    dispatch_level(shadow_map, chain, level, runs[static_cast<size_t>(level)], texels.buffer());
}

MinMaxMipChain MinMaxMipBuilder::build(const GlObject& shadow_map, int map_size) const {
  MinMaxMipChain chain = allocate(map_size);
  build_into(shadow_map, chain);
  return chain;
}

}  // namespace pn
