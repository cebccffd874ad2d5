// Runner side of glsl/passes/cascade_blend.comp: the visibilities a technique
// produced on each cascade, blended into one by view depth.
#pragma once

#include <vector>

#include "gl/compute_program.h"
#include "gl/texture.h"
#include "shader/source_tree.h"
#include "technique/technique.h"

namespace pn {

class CascadeBlendPass {
 public:
  CascadeBlendPass(const Context& context, const SourceTree& tree);

  // One screen² R32F visibility from `visibilities` (one a layer of `cascades`, screen² R32F).
  FloatTexture run(const CascadeInputs& cascades, const std::vector<const GlObject*>& visibilities,
                   int screen_size) const;

 private:
  const Context* context_;
  ComputeProgram program_;
  GlObject unused_;  // bound where a cascade is missing (1×1, never read)
};

}  // namespace pn
