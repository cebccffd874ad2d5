#include "pass_runners/traversal_pass.h"

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/std140.h"

namespace pn::glsl {
#include "passes/traversal_query.h"
#include "passes/window_scan.h"
PN_STD140_SIZE(PnTraversalQueryParams, 48);
PN_STD140_OFFSET(PnTraversalQueryParams, leafDivisor, 32);
PN_STD140_OFFSET(PnTraversalQueryParams, mapSize, 24);
PN_STD140_OFFSET(PnTraversalQueryParams, grid, 28);
PN_STD140_OFFSET(PnTraversalQueryParams, leafSide, 4);
PN_STD140_OFFSET(PnTraversalQueryParams, leafMode, 8);
PN_STD140_OFFSET(PnTraversalQueryParams, nodeBudget, 12);
PN_STD140_SIZE(PnWindowScanParams, 16);
}  // namespace pn::glsl

namespace pn {

std::unique_ptr<DeviceTexture> upload_sample_table(const QueryDevice& device, const SampleTable& table) {
  return device.upload(table.image());
}

namespace {

std::vector<Image> batch_inputs(const std::vector<TraversalQuery>& queries, bool area_regions) {
  std::vector<Query> a, b, e;
  for (const TraversalQuery& q : queries) {
    a.push_back(area_regions ? Query{q.area_x, q.area_y, q.area_side, 0.0f}
                             : Query{float(q.region.x), float(q.region.y), float(q.region.width), float(q.region.height)});
    b.push_back({q.receiver_depth, float(q.pixel_x), float(q.pixel_y), 0.0f});
    e.push_back({q.receiver_u, q.receiver_v, q.gradient_u, q.gradient_v});
  }
  return {query_image(a), query_image(b), query_image(e)};
}

}  // namespace

TraversalBatch::TraversalBatch(const QueryDevice& device, const std::vector<TraversalQuery>& queries, bool area_regions)
    : count_(queries.size()), batch_(device.make_batch(batch_inputs(queries, area_regions), 2, 0)) {}

std::vector<TraversalReadback> TraversalBatch::read() const {
  const QueryResults r = batch_->read();
  std::vector<TraversalReadback> out;
  for (std::size_t k = 0; k < count_; ++k) {
    const Query c = r.at(0, k), d = r.at(1, k);
    TraversalReadback o;
    o.occluders = c[0], o.depth_sum = c[1], o.texels = c[2];
    o.nodes = static_cast<long>(d[0]), o.fetches = static_cast<long>(d[1]);
    o.called_blocker_mean = d[2], o.called_occluded_fraction = d[3];
    out.push_back(o);
  }
  return out;
}

TraversalPass::TraversalPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/traversal_query.comp",
             {{PN_TRAVERSAL_QUERY_A_BINDING, PN_TRAVERSAL_QUERY_B_BINDING, PN_TRAVERSAL_QUERY_PLANE_BINDING},
              {PN_TRAVERSAL_QUERY_RESULT_C_BINDING, PN_TRAVERSAL_QUERY_RESULT_D_BINDING}}),
      empty_array_(device.make_texture({TexelFormat::rgba32f, 1, 1, 1, 1, true})),
      empty_2d_(device.make_texture({TexelFormat::rgba32f, 1, 1})),
      empty_uint_(device.make_texture({TexelFormat::rgba32ui, 1, 1})) {}

void TraversalPass::dispatch(const TraversalStructure& structure, const DeviceTexture& sample_table,
                             const TraversalBatch& batch, const TraversalSettings& settings) const {
  const bool mip = structure.mip != nullptr;
  if (mip == (structure.pyramid != nullptr) || (mip && settings.depth_sums == DepthSums::table && !structure.depth_sums))
    throw Error("traversal: expected a pyramid or a mip chain (with its summed-area table for table depth sums)");
  if (settings.area_regions && settings.grid > 0)
    throw Error("traversal: area regions: expected the traversal, not the grid");
  const glsl::PnTraversalQueryParams block{settings.bias,
                                           settings.leaf_side,
                                           static_cast<int>(settings.leaf_mode),
                                           settings.node_budget,
                                           mip ? PN_STRUCTURE_MIP : PN_STRUCTURE_PYRAMID,
                                           static_cast<int>(settings.depth_sums),
                                           mip ? structure.mip->map_size : structure.pyramid->map_size,
                                           settings.grid,
                                           settings.leaf_divisor,
                                           settings.area_regions ? 1 : 0,
                                           settings.region_leaf ? 1 : 0,
                                           0};
  query_.dispatch(*batch.batch_,
                  {{PN_TRAVERSAL_QUERY_PYRAMID_BINDING, mip ? *empty_array_ : *structure.pyramid->texture},
                   {PN_TRAVERSAL_QUERY_MIP_BINDING, mip ? *structure.mip->texture : *empty_2d_},
                   {PN_TRAVERSAL_QUERY_MAP_BINDING, mip ? structure.mip->built_map() : *empty_2d_},
                   {PN_TRAVERSAL_QUERY_DEPTH_SUMS_BINDING,
                    mip && structure.depth_sums ? *structure.depth_sums->texture : *empty_uint_},
                   {PN_TRAVERSAL_QUERY_SAMPLE_TABLE_BINDING, sample_table}},
                  query_block(block));
}

WindowScanPass::WindowScanPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/window_scan.comp",
             {{PN_WINDOW_SCAN_A_BINDING, PN_WINDOW_SCAN_B_BINDING, PN_WINDOW_SCAN_PLANE_BINDING},
              {PN_WINDOW_SCAN_RESULT_C_BINDING, PN_WINDOW_SCAN_RESULT_D_BINDING}}) {}

void WindowScanPass::dispatch(const DepthPyramid& pyramid, const TraversalBatch& batch, float bias) const {
  const glsl::PnWindowScanParams block{bias};
  query_.dispatch(*batch.batch_, {{PN_WINDOW_SCAN_PYRAMID_BINDING, *pyramid.texture}}, query_block(block));
}

}  // namespace pn
