#include "passes/depth_cache_pass.h"

#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/depth_cache.h"
PN_STD140_SIZE(PnDepthCacheComposeParams, 16);
PN_STD140_OFFSET(PnDepthCacheComposeParams, texelCount, 4);
}  // namespace pn::glsl

namespace pn {

DepthCacheComposer::DepthCacheComposer(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/depth_cache_compose.comp")),
      no_texels_(make_buffer(context, 2 * sizeof(int), nullptr)) {}

void DepthCacheComposer::compose(const GlObject& static_map, const GlObject& dynamic_map, const GlObject& composed,
                                 int n, TexelRun run, const TexelList* texels) const {
  const bool listed = texels && run.count > 0 && !run.whole;
  PassBindings bind(*context_);
  bind.uniform(glsl::PnDepthCacheComposeParams{run.first, listed ? run.count : 0});
  bind.texture(PN_DEPTH_CACHE_STATIC_BINDING, static_map);
  bind.texture(PN_DEPTH_CACHE_DYNAMIC_BINDING, dynamic_map);
  bind.image(PN_DEPTH_CACHE_COMPOSED_IMAGE, composed, GL_WRITE_ONLY, GL_R32F);
  bind.storage_buffer(PN_DEPTH_CACHE_TEXELS_BINDING, listed ? texels->buffer() : no_texels_);
  dispatch_texel_run(program_, texels ? run : TexelRun{0, 0, true}, n, n);
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
