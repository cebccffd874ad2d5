#include "passes/poisson_pcss_pass.h"

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
PN_STD140_SIZE(PnPoissonQueryParams, 16 * PN_POISSON_MAX_SAMPLES + 16);
PN_STD140_OFFSET(PnPoissonQueryParams, points[1], 16);
PN_STD140_OFFSET(PnPoissonQueryParams, inPlace, 16 * PN_POISSON_MAX_SAMPLES);
}  // namespace pn::glsl

namespace pn {

PoissonPcssQueryPass::PoissonPcssQueryPass(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/poisson_pcss_query.comp")),
      block_program_(compile_pass(context, tree, "passes/poisson_pcss_query.comp", {{"PN_QUERY_DISK_IN_BLOCK", "1"}})) {}

std::vector<PoissonPcssGpuResult> PoissonPcssQueryPass::run(const GlObject& depth_map,
                                                            const std::vector<Sample>& points, PoissonDiskSource source,
                                                            const std::vector<PoissonPcssGpuQuery>& queries) const {
  if (queries.empty()) return {};
  if (points.size() > PN_POISSON_MAX_SAMPLES)
    throw Error("Poisson disk of " + std::to_string(points.size()) + " points: expected at most " +
                std::to_string(PN_POISSON_MAX_SAMPLES));
  glsl::PnPoissonQueryParams block{};
  for (size_t i = 0; i < points.size(); ++i) block.points[i] = {points[i].x, points[i].y};
  block.inPlace = source == PoissonDiskSource::parameter ? 0 : 1;

  std::vector<Query> a, b;
  for (const PoissonPcssGpuQuery& q : queries) {
    a.push_back({q.centre_x, q.centre_y, q.diameter, q.receiver_depth});
    b.push_back({q.bias, float(q.count), q.rotation_x, q.rotation_y});
  }
  const Image image_a = query_image(a), image_b = query_image(b);
  const GlObject texture_a = upload_float_texture(*context_, image_a);
  const GlObject texture_b = upload_float_texture(*context_, image_b);
  const GlObject results = make_float_texture(*context_, image_a.width, image_a.height, 4);
  {
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_POISSON_QUERY_MAP_BINDING, depth_map);
    bind.texture(PN_POISSON_QUERY_A_BINDING, texture_a);
    bind.texture(PN_POISSON_QUERY_B_BINDING, texture_b);
    bind.image(PN_POISSON_QUERY_RESULT_IMAGE, results, GL_WRITE_ONLY, GL_RGBA32F);
    (source == PoissonDiskSource::block ? block_program_ : program_).dispatch(image_a.width, image_a.height);
  }
  const Image r = read_float_texture(*context_, results, image_a.width, image_a.height, 4);
  std::vector<PoissonPcssGpuResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Query q = query_result(r, k);
    out.push_back({q[0], q[1], q[2]});
  }
  return out;
}

}  // namespace pn
