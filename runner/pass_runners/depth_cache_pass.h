// Runner side of glsl/passes/depth_cache_compose.comp and depth_cache_query.comp:
// depth_cache.glsl's composition of a static and a dynamic map, written into
// a composed map (everywhere or over a list of texels), and its shadow test
// over a batch of receivers (for the check).
#pragma once

#include <vector>

#include "core/image.h"
#include "gl/compute_program.h"
#include "device/texel_list.h"
#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

class DepthCacheComposer {
 public:
  DepthCacheComposer(const QueryDevice& device, const SourceTree& tree);
  // composed := min(static, dynamic) over the whole n×n map (no list) or the texels of `run` in
  // `texels` (uploaded). All three maps n×n R32F (`composed` of that shape: a storage image).
  void compose(const DeviceTexture& static_map, const DeviceTexture& dynamic_map, const DeviceTexture& composed, int n,
               TexelRun run = {0, 0, true}, const TexelList* texels = nullptr) const;

 private:
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
  std::unique_ptr<DeviceBuffer> no_texels_;
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
  DepthCacheQueryPass(const QueryDevice& device, const SourceTree& tree);
  std::vector<DepthCacheResult> run(const DeviceTexture& static_map, const DeviceTexture& dynamic_map,
                                    const std::vector<DepthCacheQuery>& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
