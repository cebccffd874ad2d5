#include "passes/traversal_pass.h"

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/traversal_query.h"
#include "passes/window_scan.h"
PN_STD140_SIZE(PnTraversalQueryParams, 32);
PN_STD140_OFFSET(PnTraversalQueryParams, mapSize, 24);
PN_STD140_OFFSET(PnTraversalQueryParams, leafSide, 4);
PN_STD140_OFFSET(PnTraversalQueryParams, leafMode, 8);
PN_STD140_OFFSET(PnTraversalQueryParams, nodeBudget, 12);
PN_STD140_SIZE(PnWindowScanParams, 16);
}  // namespace pn::glsl

namespace pn {

GlObject upload_sample_table(const Context& context, const SampleTable& table) {
  return upload_float_texture(context, table.image());
}

TraversalBatch::TraversalBatch(const Context& context, const std::vector<TraversalQuery>& queries)
    : context_(&context), count_(static_cast<int>(queries.size())) {
  std::vector<Query> a, b;
  for (const TraversalQuery& q : queries) {
    a.push_back({float(q.region.x), float(q.region.y), float(q.region.width), float(q.region.height)});
    b.push_back({q.receiver_depth, float(q.pixel_x), float(q.pixel_y), 0.0f});
  }
  const Image image_a = query_image(a), image_b = query_image(b);
  width_ = image_a.width, height_ = image_a.height;
  query_a_ = upload_float_texture(context, image_a);
  query_b_ = upload_float_texture(context, image_b);
  result_c_ = make_float_texture(context, width_, height_, 4);
  result_d_ = make_float_texture(context, width_, height_, 4);
}

std::vector<TraversalResult> TraversalBatch::read() const {
  const Image c = read_float_texture(*context_, result_c_, width_, height_, 4);
  const Image d = read_float_texture(*context_, result_d_, width_, height_, 4);
  std::vector<TraversalResult> out;
  for (int k = 0; k < count_; ++k) {
    const int x = k % width_, y = k / width_;
    out.push_back({c.at(x, y, 0), c.at(x, y, 1), c.at(x, y, 2), static_cast<long>(d.at(x, y, 0)),
                   static_cast<long>(d.at(x, y, 1))});
  }
  return out;
}

TraversalPass::TraversalPass(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/traversal_query.comp")),
      empty_array_(make_placeholder_texture(context, GL_TEXTURE_2D_ARRAY, GL_RGBA32F)),
      empty_2d_(make_placeholder_texture(context, GL_TEXTURE_2D, GL_RGBA32F)),
      empty_uint_(make_placeholder_texture(context, GL_TEXTURE_2D, GL_RGBA32UI)) {}

void TraversalPass::dispatch(const TraversalStructure& structure, const GlObject& sample_table,
                             const TraversalBatch& batch, const TraversalSettings& settings) const {
  const bool mip = structure.mip != nullptr;
  if (mip == (structure.pyramid != nullptr) || (mip && settings.depth_sums == DepthSums::table && !structure.depth_sums))
    throw Error("traversal: expected a pyramid or a mip chain (with its summed-area table for table depth sums)");
  const glsl::PnTraversalQueryParams block{settings.bias,
                                           settings.leaf_side,
                                           static_cast<int>(settings.leaf_mode),
                                           settings.node_budget,
                                           mip ? PN_STRUCTURE_MIP : PN_STRUCTURE_PYRAMID,
                                           static_cast<int>(settings.depth_sums),
                                           mip ? structure.mip->map_size : 0};
  PassBindings bind(*context_);
  bind.uniform(block);
  bind.texture(PN_TRAVERSAL_QUERY_PYRAMID_BINDING, mip ? empty_array_ : structure.pyramid->texture);
  bind.texture(PN_TRAVERSAL_QUERY_MIP_BINDING, mip ? structure.mip->texture : empty_2d_);
  bind.texture(PN_TRAVERSAL_QUERY_DEPTH_SUMS_BINDING,
               mip && structure.depth_sums ? structure.depth_sums->texture : empty_uint_);
  bind.texture(PN_TRAVERSAL_QUERY_SAMPLE_TABLE_BINDING, sample_table);
  bind.texture(PN_TRAVERSAL_QUERY_A_BINDING, batch.query_a_);
  bind.texture(PN_TRAVERSAL_QUERY_B_BINDING, batch.query_b_);
  bind.image(PN_TRAVERSAL_QUERY_RESULT_C_BINDING, batch.result_c_, GL_WRITE_ONLY, GL_RGBA32F);
  bind.image(PN_TRAVERSAL_QUERY_RESULT_D_BINDING, batch.result_d_, GL_WRITE_ONLY, GL_RGBA32F);
  program_.dispatch(batch.width_, batch.height_);
}

WindowScanPass::WindowScanPass(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/window_scan.comp")) {}

void WindowScanPass::dispatch(const DepthPyramid& pyramid, const TraversalBatch& batch, float bias) const {
  const glsl::PnWindowScanParams block{bias};
  PassBindings bind(*context_);
  bind.uniform(block);
  bind.texture(PN_WINDOW_SCAN_PYRAMID_BINDING, pyramid.texture);
  bind.texture(PN_WINDOW_SCAN_A_BINDING, batch.query_a_);
  bind.texture(PN_WINDOW_SCAN_B_BINDING, batch.query_b_);
  bind.image(PN_WINDOW_SCAN_RESULT_C_BINDING, batch.result_c_, GL_WRITE_ONLY, GL_RGBA32F);
  bind.image(PN_WINDOW_SCAN_RESULT_D_BINDING, batch.result_d_, GL_WRITE_ONLY, GL_RGBA32F);
  program_.dispatch(batch.width_, batch.height_);
}

}  // namespace pn
