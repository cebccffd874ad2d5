// Runner side of glsl/passes/light_depth_query.comp: light_model.glsl's
// pnLightDepthFromDepthBuffer for a batch of depth-buffer values, and pnLightProject of world points.
#pragma once

#include <glm/glm.hpp>

#include "core/image.h"
#include "pass_runners/query_pass.h"

namespace pn {

class LightDepthQueryPass {
 public:
  LightDepthQueryPass(const QueryDevice& device, const SourceTree& tree);
  // `queries`: RGBA (depth-buffer value, world x, y, z) per texel; returns RGBA (linear depth read
  // with OpenGL's [-1, 1] clip range, with a [0, 1] clip range, pnLightProject(light_view,
  // light_projection, map_size, world).xy) of the same size.
  Image run(const glm::mat4& light_projection, const Image& queries, const glm::mat4& light_view = glm::mat4(1.0f),
            float map_size = 1.0f) const;

 private:
  QueryPass query_;
};

}  // namespace pn
