// Runner side of glsl/passes/minmax_mip_build.comp: glsl/minmax_mip.glsl's
// aligned min/max mip chain, padded to a power of two — the structure Fast
// PCSS traverses (with a summed-area table of depth), and the baseline of
// `penumbra bench pyramid`.
#pragma once

#include <cstddef>
#include <vector>

#include <memory>

#include "core/image.h"
#include "core/texel_rect.h"
#include "device/query_device.h"
#include "device/texel_list.h"
#include "minmax_mip.h"  // PN_MIP_FIRST_LEVEL
#include "shader/source_tree.h"

namespace pn {

// Node levels from first_level (PN_MIP_FIRST_LEVEL, glsl/minmax_mip.h) to top_level = log2 P; the
// levels below are the map itself. Mip level k of the texture holds node level first_level + k.
struct MinMaxMipChain {
  std::unique_ptr<DeviceTexture> texture;  // RGBA32F, (P/8)×(P/4), log2 P - 1 mip levels, two nodes a texel; P = the least power of two >= max(map_size, 4)
  int map_size = 0;
  int padded_size = 0;  // P
  static constexpr int first_level = PN_MIP_FIRST_LEVEL;  // the node level of the texture's mip 0
  int top_level = 0;                                      // log2 P: mips top_level - first_level + 1
  // The map it was last built from, not owned: every reader binds it beside the chain (its texels,
  // and the levels below first_level). It must outlive the chain's use.
  const DeviceTexture* map = nullptr;
  // *map; throws Error before the chain was built.
  const DeviceTexture& built_map() const;

  static int padded_size_for(int map_size);
  static std::size_t memory_bytes(int map_size);  // 16 bytes × texels of every level (8 a node)
  // Texels of node level `level`: P / 2^level rows, half as many (at least one) across.
  int level_rows(int level) const { return padded_size >> level; }
  int level_width(int level) const { return level_rows(level) / 2 > 0 ? level_rows(level) / 2 : 1; }
};

// Node level `level` (first_level..top_level) read back as the texture holds it: texel (c, r) =
// nodes 2c and 2c + 1 of row r.
Image read_mip_chain_level(const QueryDevice& device, const MinMaxMipChain& chain, int level);

// Builds on any executor (device/query_device.h); on GL the map is a GlDeviceTexture of a GL
// pass's map and the chain's texture a GL texture (gl_texture).
class MinMaxMipBuilder {
 public:
  MinMaxMipBuilder(const QueryDevice& device, const SourceTree& tree);
  // Throws Error unless 1 <= map_size and its power of two is within the device's texture size.
  MinMaxMipChain allocate(int map_size) const;
  void build_into(const DeviceTexture& shadow_map, MinMaxMipChain& chain) const;
  // Node levels first..last only (one dispatch each), the levels below first already built: what
  // `bench pyramid` times the first dispatch (the map read) apart from the whole build.
  void build_levels(const DeviceTexture& shadow_map, MinMaxMipChain& chain, int first, int last) const;
  // allocate + build_into, for a map_size × map_size R32F shadow map.
  MinMaxMipChain build(const DeviceTexture& shadow_map, int map_size) const;

  // Rebuilds only what changed where the map changed in `rects` (a shadow-map cache's dirty
  // rectangles): at node level i the nodes holding a texel of a rectangle — each rectangle rounded out
  // to whole 2^i × 2^i nodes — as one dispatch a level over their texels (where rectangles
  // overlap, a texel is computed twice, to the same value). Everything else of the
  // chain must already be the chain of the map as it is outside the rectangles.
  // `round_out` false rounds the rectangles' far ends in: the broken rule a check must catch.
  void update_into(const DeviceTexture& shadow_map, MinMaxMipChain& chain, const std::vector<TexelRect>& rects,
                   TexelList& texels, bool round_out = true) const;

 private:
  void dispatch_level(const DeviceTexture& shadow_map, const MinMaxMipChain& chain, int level, TexelRun run,
                      const DeviceBuffer& texels) const;
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
  std::unique_ptr<DeviceBuffer> no_texels_;
};

}  // namespace pn
