#include "pass_runners/poisson_pcss_pass.h"

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/poisson_pcss_query.h"
PN_STD140_SIZE(PnPoissonQueryParams, 16 * PN_POISSON_MAX_SAMPLES);
PN_STD140_OFFSET(PnPoissonQueryParams, points[1], 16);
}  // namespace pn::glsl

namespace pn {
namespace {

QueryBindings bindings() {
  return {{PN_POISSON_QUERY_A_BINDING, PN_POISSON_QUERY_B_BINDING}, {PN_POISSON_QUERY_RESULT_IMAGE}};
}

}  // namespace

PoissonPcssQueryPass::PoissonPcssQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/poisson_pcss_query.comp", bindings()),
      block_query_(device, tree, "passes/poisson_pcss_query.comp", bindings(), {{"PN_QUERY_DISK_IN_BLOCK", "1"}}) {}

std::vector<PoissonPcssGpuResult> PoissonPcssQueryPass::run(const DeviceTexture& depth_map,
                                                            const std::vector<Sample>& points, PoissonDiskSource source,
                                                            const std::vector<PoissonPcssGpuQuery>& queries) const {
  if (queries.empty()) return {};
  if (points.size() > PN_POISSON_MAX_SAMPLES)
    throw Error("Poisson disk of " + std::to_string(points.size()) + " points: expected at most " +
                std::to_string(PN_POISSON_MAX_SAMPLES));
  glsl::PnPoissonQueryParams block{};
  for (size_t i = 0; i < points.size(); ++i) block.points[i] = {points[i].x, points[i].y};

  std::vector<Query> a, b;
  for (const PoissonPcssGpuQuery& q : queries) {
    a.push_back({q.centre_x, q.centre_y, q.diameter, q.receiver_depth});
    b.push_back({q.bias, float(q.count), q.rotation_x, q.rotation_y});
  }
  const QueryResults r = (source == PoissonDiskSource::block ? block_query_ : query_)
                             .run({a, b}, {{PN_POISSON_QUERY_MAP_BINDING, depth_map}}, query_block(block));
  std::vector<PoissonPcssGpuResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query q = r.at(0, k);
    out.push_back({q[0], q[1], q[2], q[3]});
  }
  return out;
}

}  // namespace pn
