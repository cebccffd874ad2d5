#include "passes/traversal_pass.h"

#include <cstdint>

#include "core/query_grid.h"
#include "gl/texture.h"

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
    : context_(&context), program_(compile_pass(context, tree, "passes/traversal_query.comp")) {}

void TraversalPass::dispatch(const DepthPyramid& pyramid, const GlObject& sample_table, const TraversalBatch& batch,
                             const TraversalSettings& settings) const {
  struct Block {
    float bias;
    std::int32_t leaf_side, leaf_mode, node_budget;
  } block{settings.bias, settings.leaf_side, static_cast<std::int32_t>(settings.leaf_mode), settings.node_budget};
  GlObject params = bind_uniform_buffer(*context_, 6, &block, sizeof block);
  const auto& gl = context_->gl();
  gl.BindTextureUnit(0, pyramid.texture.id());
  gl.BindTextureUnit(1, sample_table.id());
  gl.BindTextureUnit(2, batch.query_a_.id());
  gl.BindTextureUnit(5, batch.query_b_.id());
  gl.BindImageTexture(3, batch.result_c_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl.BindImageTexture(4, batch.result_d_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  program_.dispatch(batch.width_, batch.height_);
}

WindowScanPass::WindowScanPass(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/window_scan.comp")) {}

void WindowScanPass::dispatch(const DepthPyramid& pyramid, const TraversalBatch& batch, float bias) const {
  const float block[4] = {bias, 0.0f, 0.0f, 0.0f};
  GlObject params = bind_uniform_buffer(*context_, 6, block, sizeof block);
  const auto& gl = context_->gl();
  gl.BindTextureUnit(0, pyramid.texture.id());
  gl.BindTextureUnit(2, batch.query_a_.id());
  gl.BindTextureUnit(5, batch.query_b_.id());
  gl.BindImageTexture(3, batch.result_c_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl.BindImageTexture(4, batch.result_d_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  program_.dispatch(batch.width_, batch.height_);
}

}  // namespace pn
