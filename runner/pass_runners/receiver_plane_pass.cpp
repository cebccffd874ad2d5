#include "pass_runners/receiver_plane_pass.h"

#include "passes/receiver_plane_query.h"

namespace pn {

ReceiverPlaneQueryPass::ReceiverPlaneQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/receiver_plane_query.comp",
             QueryBindings{{PN_RECEIVER_PLANE_QUERY_CENTRE_BINDING, PN_RECEIVER_PLANE_QUERY_LEFT_BINDING,
                            PN_RECEIVER_PLANE_QUERY_RIGHT_BINDING, PN_RECEIVER_PLANE_QUERY_BELOW_BINDING,
                            PN_RECEIVER_PLANE_QUERY_ABOVE_BINDING, PN_RECEIVER_PLANE_QUERY_F_BINDING,
                            PN_RECEIVER_PLANE_QUERY_G_BINDING},
                           {PN_RECEIVER_PLANE_QUERY_RESULT_IMAGE, PN_RECEIVER_PLANE_QUERY_THRESHOLD_IMAGE},
                           {}}) {}

std::vector<ReceiverPlaneGpuResult> ReceiverPlaneQueryPass::run(const std::vector<ReceiverPlaneGpuQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<std::vector<Query>> inputs(7);
  for (const ReceiverPlaneGpuQuery& q : queries) {
    for (size_t i = 0; i < 5; ++i) inputs[i].push_back(q.entries[i]);
    inputs[5].push_back({q.max_slope, static_cast<float>(q.origin_x), static_cast<float>(q.origin_y),
                         static_cast<float>(q.size_x)});
    inputs[6].push_back({static_cast<float>(q.size_y), q.gradient_x, q.gradient_y, 0.0f});
  }
  const QueryResults r = query_.run(inputs);
  std::vector<ReceiverPlaneGpuResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query q = r.at(0, k), t = r.at(1, k);
    out.push_back({q[0], q[1], q[2], q[3], t[0], t[1], t[2]});
  }
  return out;
}

}  // namespace pn
