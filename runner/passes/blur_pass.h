// Runner side of glsl/passes/blur.comp: the two 1-D dispatches (x, then y)
// that blur an R32F texture with glsl/blur.glsl.
#pragma once

#include "gl/compute_program.h"
#include "reference/blur_reference.h"
#include "shader/source_tree.h"

namespace pn {

class BlurPass {
 public:
  // Flattens and compiles passes/blur.comp from `tree` (a user's copy under --glsl-root too).
  BlurPass(const Context& context, const SourceTree& tree);

  // Returns a new width × height R32F texture. `depth` (same size) is read
  // only when params.depth_aware. Throws Error for invalid params.
  GlObject run(const GlObject& source, const GlObject* depth, int width, int height, const BlurParams& params) const;

 private:
  const Context* context_;
  ComputeProgram program_;
};

}  // namespace pn
