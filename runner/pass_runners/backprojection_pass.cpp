#include "pass_runners/backprojection_pass.h"

#include <string>

#include "core/error.h"
#include "gl/std140.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/backprojection_query.h"
PN_STD140_SIZE(PnBackprojectionQueryParams, 32);
PN_STD140_OFFSET(PnBackprojectionQueryParams, mapSize, 12);
}  // namespace pn::glsl

namespace pn {

BackprojectionQueryPass::BackprojectionQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/backprojection_query.comp",
             {{PN_BACKPROJECTION_QUERY_A_BINDING, PN_BACKPROJECTION_QUERY_B_BINDING, PN_BACKPROJECTION_QUERY_C_BINDING},
              {PN_BACKPROJECTION_QUERY_RESULT_IMAGE}}) {}

std::vector<BackprojectionResult> BackprojectionQueryPass::run(const MinMaxMipChain& mip, const LightModel& light,
                                                               const std::vector<BackprojectionQuery>& queries,
                                                               const MinMaxMipChain* second_mip) const {
  if (queries.empty()) return {};
  for (const MinMaxMipChain* chain : {&mip, second_mip})
    if (chain != nullptr && chain->map_size != light.map_size)
      throw Error("backprojection query: light map size " + std::to_string(light.map_size) +
                  ": expected the mip chain's " + std::to_string(chain->map_size));
  glsl::PnBackprojectionQueryParams block{};
  set_light_fields(block, light);
  std::vector<Query> a, b, c;
  for (const BackprojectionQuery& q : queries) {
    a.push_back({q.u, q.v, q.depth, q.bias});
    b.push_back({static_cast<float>(q.side), q.tolerance, static_cast<float>(q.budget), q.gap});
    c.push_back({q.thickness, second_mip != nullptr ? 1.0f : 0.0f, 0.0f, 0.0f});
  }
  const MinMaxMipChain& layer = second_mip != nullptr ? *second_mip : mip;
  const QueryResults r = query_.run({a, b, c},
                                    {{PN_BACKPROJECTION_QUERY_MIP_BINDING, *mip.texture},
                                     {PN_BACKPROJECTION_QUERY_MAP_BINDING, mip.built_map()},
                                     {PN_BACKPROJECTION_QUERY_LAYER_BINDING, *layer.texture},
                                     {PN_BACKPROJECTION_QUERY_LAYER_MAP_BINDING, layer.built_map()}},
                                    query_block(block));
  std::vector<BackprojectionResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query q = r.at(0, k);
    out.push_back({q[0], q[1], q[2], q[3]});
  }
  return out;
}

}  // namespace pn
