// Runner side of glsl/passes/depth_cache_compose.comp and depth_cache_query.comp:
// depth_cache.glsl's composition of a static and a dynamic map, written into
// a composed map (everywhere or over a list of tiles), and its shadow test
// over a batch of receivers (for the check).
#pragma once

#include <vector>

#include "core/image.h"
#include "gl/compute_program.h"
#include "gl/tile_list.h"
#include "shader/source_tree.h"

namespace pn {

class DepthCacheComposer {
 public:
  DepthCacheComposer(const Context& context, const SourceTree& tree);
  // composed := min(static, dynamic) over the whole n×n map (`run` empty) or the tiles of `run` in
  // `tiles` (uploaded). All three maps n×n R32F.
  void compose(const GlObject& static_map, const GlObject& dynamic_map, const GlObject& composed, int n,
               TileRun run = {}, const TileList* tiles = nullptr) const;

 private:
  const Context* context_;
  ComputeProgram program_;
  GlObject no_tiles_;
};

struct DepthCacheQuery {
  int u = 0, v = 0;  // texel
  float receiver_depth = 0.0f, bias = 0.0f;
};

struct DepthCacheResult {
  float composed = 0.0f, visibility = 0.0f;
};

class DepthCacheQueryPass {
 public:
  DepthCacheQueryPass(const Context& context, const SourceTree& tree);
  std::vector<DepthCacheResult> run(const GlObject& static_map, const GlObject& dynamic_map,
                                    const std::vector<DepthCacheQuery>& queries) const;

 private:
  const Context* context_;
  ComputeProgram program_;
};

}  // namespace pn
