#include "passes/poisson_pcss_pass.h"

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/texture.h"
#include "poisson_pcss.h"

namespace pn {
namespace {

// passes/poisson_pcss_query.comp's PnPoissonQueryParams, std140: vec2 points[PN_POISSON_MAX_SAMPLES]
// (array stride 16: the xy of each 4-float row), then int inPlace.
constexpr GLuint kQueryBlockBinding = 4;
struct QueryBlock {
  float points[PN_POISSON_MAX_SAMPLES][4];
  std::int32_t in_place, padding[3];
};
static_assert(offsetof(QueryBlock, in_place) == 16 * PN_POISSON_MAX_SAMPLES, "std140 layout of PnPoissonQueryParams");

}  // namespace

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
  QueryBlock block{};
  for (size_t i = 0; i < points.size(); ++i) block.points[i][0] = points[i].x, block.points[i][1] = points[i].y;
  block.in_place = source == PoissonDiskSource::parameter ? 0 : 1;

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
    bind.uniform_data(kQueryBlockBinding, &block, sizeof block);
    bind.texture(0, depth_map);
    bind.texture(1, texture_a);
    bind.texture(2, texture_b);
    bind.image(3, results, GL_WRITE_ONLY, GL_RGBA32F);
    (source == PoissonDiskSource::block ? block_program_ : program_).dispatch(image_a.width, image_a.height);
  }
  const Image r = read_float_texture(*context_, results, image_a.width, image_a.height, 4);
  std::vector<PoissonPcssGpuResult> out;
  for (size_t k = 0; k < queries.size(); ++k) {
    const int x = static_cast<int>(k) % image_a.width, y = static_cast<int>(k) / image_a.width;
    out.push_back({r.at(x, y, 0), r.at(x, y, 1), r.at(x, y, 2)});
  }
  return out;
}

}  // namespace pn
