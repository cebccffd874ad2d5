// Runner side of glsl/passes/depth_pyramid_build.comp and _query.comp.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "core/image.h"
#include "core/texel_rect.h"
#include "device/query_device.h"
#include "device/texel_list.h"
#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

// A built pyramid: an N×N×levels RGBA32F array texture (see depth_pyramid.glsl).
struct DepthPyramid {
  std::unique_ptr<DeviceTexture> texture;
  int map_size = 0;
  int levels = 0;  // L + 1
  std::unique_ptr<DeviceTexture> level0;  // layer 0 as a 2-D texture (the sanitized map, .r): a sampler2D for
                                          // pcf.glsl, poisson_pcss.glsl and the passes that call them (a view,
                                          // or a copy of the layer as build() left it: QueryDevice::layer_texture)

  // Bytes of GPU memory: 16 · N² · levels.
  static std::size_t memory_bytes(int map_size, int levels);
  // Window origins a side of level `level` holds: N − 2^level + 1.
  int level_size(int level) const { return map_size - (1 << level) + 1; }
};

// Level `level` read back: level_size(level)² texels of (min, max, mean, 0).
Image read_pyramid_level(const QueryDevice& device, const DepthPyramid& pyramid, int level);

// Builds on any executor (device/query_device.h); on GL the map is a GlDeviceTexture of a GL
// pass's map and the pyramid's textures GL textures (gl_texture).
class DepthPyramidBuilder {
 public:
  DepthPyramidBuilder(const QueryDevice& device, const SourceTree& tree);

  // Builds levels 0 … min(floor(log2 N), max_level) from an N×N R32F shadow
  // map. Throws Error for a non-square map, N < 2 or max_level < 0.
  DepthPyramid build(const DeviceTexture& shadow_map, int width, int height, int max_level) const;

  // Dispatches only, into an existing pyramid (for benchmarks).
  void build_into(const DeviceTexture& shadow_map, const DepthPyramid& pyramid) const;

  // Rebuilds only what changed where the map changed in `rects` (a shadow-map cache's dirty
  // rectangles): at level i every window that holds a texel of a rectangle — each rectangle
  // dilated by the window's side less one towards the origin (2^i - 1 texels, up to the largest
  // window's) — as one dispatch a level over their texels (where they overlap, a texel is
  // computed twice, to the same value); then re-takes level0 (a copy where
  // the context has no views). Everything else must already be the pyramid of the map as it is
  // outside the rectangles. `dilate` false is the broken rule a check must catch.
  void update_into(const DeviceTexture& shadow_map, DepthPyramid& pyramid, const std::vector<TexelRect>& rects,
                   TexelList& texels, bool dilate = true) const;

 private:
  void dispatch_level(const DeviceTexture& shadow_map, const DepthPyramid& pyramid, int level, TexelRun run,
                      const DeviceBuffer& texels) const;
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
  std::unique_ptr<DeviceBuffer> no_texels_;
};

class DepthPyramidQuery {
 public:
  DepthPyramidQuery(const QueryDevice& device, const SourceTree& tree);

  // `queries` is RGBA (u, v, side, -) per texel; returns RGBA (min, max, 0, 0) of the same size.
  Image run(const DepthPyramid& pyramid, const Image& queries) const;

 private:
  QueryPass query_;
};

// Throws Error naming the map unless it is square with N >= 2.
void validate_shadow_map_size(int width, int height);

}  // namespace pn
