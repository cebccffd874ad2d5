#include "pass_runners/depth_cache_pass.h"

#include "core/query_grid.h"
#include "gl/std140.h"

namespace pn::glsl {
#include "passes/depth_cache.h"
PN_STD140_SIZE(PnDepthCacheComposeParams, 16);
PN_STD140_OFFSET(PnDepthCacheComposeParams, texelCount, 4);
}  // namespace pn::glsl

namespace pn {

DepthCacheComposer::DepthCacheComposer(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_query(tree, "passes/depth_cache_compose.comp", {})),
      no_texels_(device.make_buffer(2 * sizeof(int))) {}

void DepthCacheComposer::compose(const DeviceTexture& static_map, const DeviceTexture& dynamic_map,
                                 const DeviceTexture& composed, int n, TexelRun run, const TexelList* texels) const {
  const bool listed = texels && run.count > 0 && !run.whole;
  const glsl::PnDepthCacheComposeParams block{run.first, listed ? run.count : 0};
  const auto [width, height] = texel_run_grid(texels ? run : TexelRun{0, 0, true}, n, n);
  device_->run(*program_,
               {{{PN_DEPTH_CACHE_STATIC_BINDING, static_map}, {PN_DEPTH_CACHE_DYNAMIC_BINDING, dynamic_map}},
                {{PN_DEPTH_CACHE_COMPOSED_IMAGE, composed}},
                {{PN_DEPTH_CACHE_TEXELS_BINDING, listed ? texels->buffer() : *no_texels_}},
                query_block(block)},
               width, height);
}

DepthCacheQueryPass::DepthCacheQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/depth_cache_query.comp",
             {{PN_DEPTH_CACHE_QUERIES_BINDING}, {PN_DEPTH_CACHE_RESULTS_IMAGE}}) {}

std::vector<DepthCacheResult> DepthCacheQueryPass::run(const DeviceTexture& static_map, const DeviceTexture& dynamic_map,
                                                       const std::vector<DepthCacheQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> q;
  for (const DepthCacheQuery& k : queries) q.push_back({float(k.u), float(k.v), k.receiver_depth, k.bias});
  const QueryResults r = query_.run(
      {q}, {{PN_DEPTH_CACHE_STATIC_BINDING, static_map}, {PN_DEPTH_CACHE_DYNAMIC_BINDING, dynamic_map}});
  std::vector<DepthCacheResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query v = r.at(0, k);
    out.push_back({v[0], v[1]});
  }
  return out;
}

}  // namespace pn
