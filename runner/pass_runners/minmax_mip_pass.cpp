#include "pass_runners/minmax_mip_pass.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "gl/std140.h"
#include "modules/depth_pyramid_face.h"

namespace pn::glsl {
#include "passes/minmax_mip_build.h"
PN_STD140_SIZE(PnMipBuildParams, 16);
PN_STD140_OFFSET(PnMipBuildParams, texelCount, 8);
}  // namespace pn::glsl

namespace pn {

int MinMaxMipChain::padded_size_for(int map_size) {
  int p = 1 << first_level;  // the first level's one node at least
  while (p < map_size && p < (1 << 30)) p *= 2;
  return p;
}

std::size_t MinMaxMipChain::memory_bytes(int map_size) {
  std::size_t texels = 0;
  for (int side = padded_size_for(map_size) >> first_level; side >= 1; side /= 2)
    texels += static_cast<std::size_t>(std::max(side / 2, 1)) * side;
  return 16 * texels;  // RGBA32F texels, two nodes each
}

const DeviceTexture& MinMaxMipChain::built_map() const {
  if (map == nullptr) throw Error("min/max mip chain: read before it was built from a map");
  return *map;
}

Image read_mip_chain_level(const QueryDevice& device, const MinMaxMipChain& chain, int level) {
  if (level < chain.first_level || level > chain.top_level)
    throw Error("min/max mip chain level " + std::to_string(level) + ": expected " +
                std::to_string(chain.first_level) + ".." + std::to_string(chain.top_level));
  return device.read_texture(*chain.texture, level - chain.first_level);
}

MinMaxMipBuilder::MinMaxMipBuilder(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_query(tree, "passes/minmax_mip_build.comp", {})),
      no_texels_(device.make_buffer(2 * sizeof(int))) {}

MinMaxMipChain MinMaxMipBuilder::allocate(int map_size) const {
  if (map_size < 1) throw Error("min/max mip chain of a " + std::to_string(map_size) + "² map: expected 1 <= N");
  MinMaxMipChain chain;
  chain.map_size = map_size;
  chain.padded_size = MinMaxMipChain::padded_size_for(map_size);
  chain.top_level = floor_log2(chain.padded_size);
  chain.texture = device_->make_texture({TexelFormat::rgba32f, chain.level_width(chain.first_level),
                                         chain.level_rows(chain.first_level),
                                         chain.top_level - chain.first_level + 1, 1, false});
  return chain;
}

void MinMaxMipBuilder::dispatch_level(const DeviceTexture& shadow_map, const MinMaxMipChain& chain, int level,
                                      TexelRun run, const DeviceBuffer& texels) const {
  if (!run.whole && run.count <= 0) return;
  const bool listed = run.count > 0 && !run.whole;
  const glsl::PnMipBuildParams block{level, run.first, listed ? run.count : 0};
  const auto [width, height] = texel_run_grid(run, chain.level_width(level), chain.level_rows(level));
  device_->run(*program_,
               {{{PN_MINMAX_MIP_SHADOW_MAP_BINDING, shadow_map}, {PN_MINMAX_MIP_READ_BINDING, *chain.texture}},
                {{PN_MINMAX_MIP_WRITE_BINDING, *chain.texture, level - chain.first_level}},
                {{PN_MINMAX_MIP_TEXELS_BINDING, listed ? texels : *no_texels_}},
                query_block(block)},
               width, height);
}

void MinMaxMipBuilder::build_into(const DeviceTexture& shadow_map, MinMaxMipChain& chain) const {
  build_levels(shadow_map, chain, chain.first_level, chain.top_level);
}

void MinMaxMipBuilder::build_levels(const DeviceTexture& shadow_map, MinMaxMipChain& chain, int first, int last) const {
  if (first < chain.first_level || last > chain.top_level)
    throw Error("mip chain levels " + std::to_string(first) + ".." + std::to_string(last) + ": expected within " +
                std::to_string(chain.first_level) + ".." + std::to_string(chain.top_level));
  chain.map = &shadow_map;
  for (int level = first; level <= last; ++level) dispatch_level(shadow_map, chain, level, {0, 0, true}, *no_texels_);
}

void MinMaxMipBuilder::update_into(const DeviceTexture& shadow_map, MinMaxMipChain& chain,
                                   const std::vector<TexelRect>& rects, TexelList& texels, bool round_out) const {
  chain.map = &shadow_map;
  texels.clear();
  std::vector<TexelRun> runs;
  std::vector<TexelRect> at_level;
  for (int level = chain.first_level; level <= chain.top_level; ++level) {
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
  texels.upload(*device_);
  for (int level = chain.first_level; level <= chain.top_level; ++level)
    dispatch_level(shadow_map, chain, level, runs[static_cast<size_t>(level - chain.first_level)], texels.buffer());
}

MinMaxMipChain MinMaxMipBuilder::build(const DeviceTexture& shadow_map, int map_size) const {
  MinMaxMipChain chain = allocate(map_size);
  build_into(shadow_map, chain);
  return chain;
}

}  // namespace pn
