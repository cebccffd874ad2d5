#include "pass_runners/vogel_pcss_pass.h"

#include "passes/vogel_pcss_query.h"

namespace pn {

VogelPcssQueryPass::VogelPcssQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/vogel_pcss_query.comp",
             QueryBindings{{PN_VOGEL_QUERY_A_BINDING, PN_VOGEL_QUERY_B_BINDING, PN_VOGEL_QUERY_C_BINDING},
                           {PN_VOGEL_QUERY_RESULT_IMAGE},
                           {}}) {}

std::vector<VogelPcssGpuResult> VogelPcssQueryPass::run(const DeviceTexture& depth_map,
                                                        const std::vector<VogelPcssGpuQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> a, b, c;
  for (const VogelPcssGpuQuery& q : queries) {
    a.push_back({q.centre_x, q.centre_y, q.diameter, q.receiver_depth});
    b.push_back({q.bias, static_cast<float>(q.count), q.turn, 0.0f});
    c.push_back({q.gradient_x, q.gradient_y, q.estimate_turn ? 1.0f : 0.0f, 0.0f});
  }
  const QueryResults r = query_.run({a, b, c}, {{PN_VOGEL_QUERY_MAP_BINDING, depth_map}}, QueryBlock{});
  std::vector<VogelPcssGpuResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query q = r.at(0, k);
    out.push_back({q[0], q[1], q[2], q[3]});
  }
  return out;
}

}  // namespace pn
