// Runner side of glsl/passes/light_depth_query.comp: light_model.glsl's
// pnLightDepthFromDepthBuffer for a batch of depth-buffer values.
#pragma once

#include <glm/glm.hpp>

#include "core/image.h"
#include "pass_runners/query_pass.h"

namespace pn {

class LightDepthQueryPass {
 public:
  LightDepthQueryPass(const QueryDevice& device, const SourceTree& tree);
  // `queries`: RGBA (depth-buffer value, -, -, -) per texel; returns RGBA (linear depth read with
  // OpenGL's [-1, 1] clip range, with a [0, 1] clip range, 0, 0) of the same size.
  Image run(const glm::mat4& light_projection, const Image& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
