#include "pass_runners/light_model_query_pass.h"

#include "gl/std140.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/light_model_query.h"
PN_STD140_SIZE(PnLightParams, 32);
PN_STD140_OFFSET(PnLightParams, lightTexelWorld, 20);
PN_STD140_OFFSET(PnLightParams, lightNearPlaneWidth, 8);
PN_STD140_OFFSET(PnLightParams, mapSize, 12);
}  // namespace pn::glsl

namespace pn {

LightModelQueryPass::LightModelQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/light_model_query.comp",
             {{PN_LIGHT_MODEL_QUERY_QUERIES_BINDING}, {PN_LIGHT_MODEL_QUERY_RESULTS_BINDING}}) {}

Image LightModelQueryPass::run(const LightModel& light, const Image& queries) const {
  glsl::PnLightParams block{};
  set_light_fields(block, light);
  return query_.run(std::vector<Image>{queries}, {}, query_block(block)).images.front();
}

}  // namespace pn
