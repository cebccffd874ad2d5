#include "passes/pcf_pass.h"

#include <string>

#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/texture.h"
#include "passes/pcf_query.h"

namespace pn {
namespace {

std::vector<Define> max_side_define(int max_side) {
  if (max_side <= 0) return {};
  return {{"PN_PCF_MAX_SIDE", std::to_string(max_side)}};
}

}  // namespace

PcfQueryPass::PcfQueryPass(const Context& context, const SourceTree& tree, int max_side)
    : context_(&context), program_(compile_pass(context, tree, "passes/pcf_query.comp", max_side_define(max_side))) {}

Image PcfQueryPass::dispatch(const GlObject& depth_map, const std::vector<Query>& a, const std::vector<Query>& b) const {
  const Image image_a = query_image(a), image_b = query_image(b);
  const GlObject texture_a = upload_float_texture(*context_, image_a);
  const GlObject texture_b = upload_float_texture(*context_, image_b);
  const GlObject results = make_float_texture(*context_, image_a.width, image_a.height, 4);
  {
    PassBindings bind(*context_);
    bind.texture(PN_PCF_QUERY_MAP_BINDING, depth_map);
    bind.texture(PN_PCF_QUERY_A_BINDING, texture_a);
    bind.texture(PN_PCF_QUERY_B_BINDING, texture_b);
    bind.image(PN_PCF_QUERY_RESULT_IMAGE, results, GL_WRITE_ONLY, GL_RGBA32F);
    program_.dispatch(image_a.width, image_a.height);
  }
  return read_float_texture(*context_, results, image_a.width, image_a.height, 4);
}

std::vector<PcfQueryResult> PcfQueryPass::run(const GlObject& depth_map, const std::vector<PcfQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> a, b;
  for (const PcfQuery& q : queries) {
    a.push_back({float(q.x), float(q.y), float(q.width), float(q.height)});
    b.push_back({q.receiver_depth, q.bias, float(q.band_rows), 0.0f});
  }
  const Image r = dispatch(depth_map, a, b);
  std::vector<PcfQueryResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query q = query_result(r, k);
    out.push_back({q[0], q[1], q[2]});
  }
  return out;
}

std::vector<float> PcfQueryPass::bilinear(const GlObject& depth_map, const std::vector<PcfBilinearQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> a, b;
  for (const PcfBilinearQuery& q : queries) {
    a.push_back({q.x, q.y, 0.0f, 0.0f});
    b.push_back({q.receiver_depth, q.bias, 0.0f, 1.0f});
  }
  const Image r = dispatch(depth_map, a, b);
  std::vector<float> out;
  for (size_t k = 0; k < queries.size(); ++k) out.push_back(query_result(r, k)[0]);
  return out;
}

}  // namespace pn
