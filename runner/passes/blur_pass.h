// Runner side of glsl/passes/blur.comp: the two 1-D dispatches (x, then y)
// that blur an R32F texture with glsl/blur.glsl.
#pragma once

#include <vector>

#include "gl/compute_program.h"
#include "reference/blur_reference.h"
#include "shader/source_tree.h"

namespace pn {

class BlurPass {
 public:
  // Flattens and compiles passes/blur.comp from `tree` (a user's copy under
  // --glsl-root too), once per variant: plain or depth-aware, fixed or adaptive radius.
  BlurPass(const Context& context, const SourceTree& tree);

  // Returns a new width × height R32F texture. `depth` (same size) is read
  // only when params.depth_aware, `filter_map` (same size, RGBA32F, the
  // filter-region map: .w = side in texels) only when params.adaptive.
  // Throws Error for invalid params, and when adaptive without a filter map.
  GlObject run(const GlObject& source, const GlObject* depth, int width, int height, const BlurParams& params,
               const GlObject* filter_map = nullptr) const;

 private:
  const Context* context_;
  std::vector<ComputeProgram> programs_;  // by variant (blur_pass.cpp)
};

}  // namespace pn
