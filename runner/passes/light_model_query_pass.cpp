#include "passes/light_model_query_pass.h"

#include "gl/std140.h"

namespace pn::glsl {
#include "passes/light_model_query.h"
PN_STD140_SIZE(PnLightParams, 32);
PN_STD140_OFFSET(PnLightParams, texelWorld, 20);
PN_STD140_OFFSET(PnLightParams, nearPlaneWidth, 8);
PN_STD140_OFFSET(PnLightParams, mapSize, 12);
}  // namespace pn::glsl

namespace pn {

LightModelQueryPass::LightModelQueryPass(const Context& context, const SourceTree& tree)
    : query_(context, tree, "passes/light_model_query.comp",
             {{PN_LIGHT_MODEL_QUERY_QUERIES_BINDING}, {PN_LIGHT_MODEL_QUERY_RESULTS_BINDING}}) {}

Image LightModelQueryPass::run(const LightModel& light, const Image& queries) const {
  const glsl::PnLightParams block{static_cast<float>(light.width),
                                  static_cast<float>(light.near_plane),
                                  static_cast<float>(light.near_plane_width()),
                                  static_cast<float>(light.map_size),
                                  static_cast<float>(light.spread),
                                  static_cast<float>(light.texel_world)};
  return query_.run(std::vector<Image>{queries}, {}, query_block(block)).images.front();
}

}  // namespace pn
