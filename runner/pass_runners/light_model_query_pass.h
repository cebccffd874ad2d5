// Runner side of glsl/passes/light_model_query.comp: light_model.glsl's
// widths for a batch of (receiver depth, blocker depth) queries.
#pragma once

#include "core/image.h"
#include "pass_runners/query_pass.h"
#include "scene/light_model.h"

namespace pn {

class LightModelQueryPass {
 public:
  LightModelQueryPass(const QueryDevice& device, const SourceTree& tree);
  // `queries`: RGBA (receiver depth, blocker depth, -, -) per texel; returns RGBA (blocker window
  // texels, search width texels, penumbra world, penumbra texels) of the same size.
  Image run(const LightModel& light, const Image& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
