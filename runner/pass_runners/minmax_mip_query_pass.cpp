#include "pass_runners/minmax_mip_query_pass.h"

#include "passes/minmax_mip_query.h"

namespace pn {

MinMaxMipQueryPass::MinMaxMipQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/minmax_mip_query.comp",
             QueryBindings{{PN_MINMAX_MIP_QUERY_A_BINDING, PN_MINMAX_MIP_QUERY_B_BINDING},
                           {PN_MINMAX_MIP_QUERY_SQUARE_IMAGE, PN_MINMAX_MIP_QUERY_COMBINE_IMAGE},
                           {}}) {}

std::vector<MinMaxMipQueryResult> MinMaxMipQueryPass::run(const MinMaxMipChain& chain,
                                                          const std::vector<MinMaxMipQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<std::vector<Query>> inputs(2);
  for (const MinMaxMipQuery& q : queries) {
    inputs[0].push_back({static_cast<float>(q.origin_x), static_cast<float>(q.origin_y), static_cast<float>(q.side),
                         static_cast<float>(chain.map_size)});
    inputs[1].push_back({static_cast<float>(q.level), static_cast<float>(q.texel_x), static_cast<float>(q.texel_y), 0.0f});
  }
  const QueryResults r = query_.run(inputs, {{PN_MINMAX_MIP_QUERY_MIP_BINDING, *chain.texture}});
  std::vector<MinMaxMipQueryResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query square = r.at(0, k), combined = r.at(1, k);
    out.push_back({square[0], square[1], {combined[0], combined[1], combined[2], combined[3]}});
  }
  return out;
}

}  // namespace pn
