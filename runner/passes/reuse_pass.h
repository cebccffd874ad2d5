// Runner side of glsl/passes/reuse_link.comp and reuse_gather.comp: parent
// codes for a map of entries, then every pixel's representative and the value
// it takes from it.
#pragma once

#include "gl/compute_program.h"
#include "gl/texture.h"
#include "modules/reuse.h"
#include "shader/source_tree.h"

namespace pn {

class ReusePass {
 public:
  ReusePass(const Context& context, const SourceTree& tree);

  // R32F parent codes (PN_REUSE_NONE, PN_REUSE_LEFT, PN_REUSE_TOP: glsl/reuse.h) of a width × height
  // RGBA32F (d, x, y, s) entry texture.
  FloatTexture link(const GlObject& entries, int width, int height, const ReuseParams& params) const;

  // RGBA32F (representative x, y, value at the representative, 0) for every pixel.
  FloatTexture gather(const GlObject& parents, const GlObject& values, int width, int height, int tile) const;

 private:
  const Context* context_;
  ComputeProgram link_, gather_;
};

}  // namespace pn
