#include "pass_runners/light_depth_query_pass.h"

#include "gl/std140.h"

namespace pn::glsl {
#include "passes/light_depth_query.h"
PN_STD140_SIZE(PnLightDepthParams, 144);
}  // namespace pn::glsl

namespace pn {

LightDepthQueryPass::LightDepthQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/light_depth_query.comp",
             {{PN_LIGHT_DEPTH_QUERY_QUERIES_BINDING}, {PN_LIGHT_DEPTH_QUERY_RESULTS_BINDING}}) {}

Image LightDepthQueryPass::run(const glm::mat4& light_projection, const Image& queries, const glm::mat4& light_view,
                               float map_size) const {
  glsl::PnLightDepthParams block{};
  block.lightProjection = glsl::std140_mat4(light_projection);
  block.lightView = glsl::std140_mat4(light_view);
  block.mapSize = map_size;
  return query_.run(std::vector<Image>{queries}, {}, query_block(block)).images.front();
}

}  // namespace pn
