// Runner side of glsl/passes/minmax_mip_build.comp: glsl/minmax_mip.glsl's
// aligned min/max mip chain, padded to a power of two — the structure Fast
// PCSS traverses (with a summed-area table of depth), and the baseline of
// `penumbra bench pyramid`.
#pragma once

#include <cstddef>
#include <vector>

#include "core/image.h"
#include "core/texel_rect.h"
#include "gl/texel_list.h"

#include "gl/compute_program.h"
#include "shader/source_tree.h"

namespace pn {

struct MinMaxMipChain {
  GlObject texture;  // RGBA32F, (P/2)×P, log2 P + 1 mip levels, two nodes a texel; P = the least power of two >= max(map_size, 2)
  int map_size = 0;
  int padded_size = 0;  // P
  int levels = 0;

  static int padded_size_for(int map_size);
  static std::size_t memory_bytes(int map_size);  // 16 bytes × texels of every level (8 a node)
  // Texels of level `level`: P / 2^level rows, half as many (at least one) across.
  int level_rows(int level) const { return padded_size >> level; }
  int level_width(int level) const { return level_rows(level) / 2 > 0 ? level_rows(level) / 2 : 1; }
};

// Level `level` read back as the texture holds it: texel (c, r) = nodes 2c and 2c + 1 of row r.
Image read_mip_chain_level(const Context& context, const MinMaxMipChain& chain, int level);

class MinMaxMipBuilder {
 public:
  MinMaxMipBuilder(const Context& context, const SourceTree& tree);
  // Throws Error unless 1 <= map_size <= GL_MAX_TEXTURE_SIZE's power of two.
  MinMaxMipChain allocate(int map_size) const;
  void build_into(const GlObject& shadow_map, const MinMaxMipChain& chain) const;
  // allocate + build_into, for a map_size × map_size R32F shadow map.
  MinMaxMipChain build(const GlObject& shadow_map, int map_size) const;

  // Rebuilds only what changed where the map changed in `rects` (a shadow-map cache's dirty
  // rectangles): at level i the nodes holding a texel of a rectangle — each rectangle rounded out
  // to whole 2^i × 2^i nodes — as one dispatch a level over their texels (where rectangles
  // overlap, a texel is computed twice, to the same value). Everything else of the
  // chain must already be the chain of the map as it is outside the rectangles.
  // `round_out` false rounds the rectangles' far ends in: the broken rule a check must catch.
  void update_into(const GlObject& shadow_map, const MinMaxMipChain& chain, const std::vector<TexelRect>& rects,
                   TexelList& texels, bool round_out = true) const;

 private:
  void dispatch_level(const GlObject& shadow_map, const MinMaxMipChain& chain, int level, TexelRun run,
                      const GlObject& texels) const;
  const Context* context_;
  ComputeProgram program_;
  GlObject no_texels_;
};

}  // namespace pn
