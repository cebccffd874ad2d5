// Runner side of glsl/passes/gbuffer.vert/.frag (Step 2): per screen pixel,
// (shadow-map u, v in texels, linear light depth, 1), or 0 where no surface is seen.
#pragma once

#include "gl/compute_program.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

class GBufferRenderer {
 public:
  GBufferRenderer(const Context& context, const SourceTree& tree);
  // RGBA32F, rows from the bottom. normal_offset_texels > 0: the point moved
  // off its face by that many shadow-map texels first (gbuffer.frag).
  GlObject render(const Scene& scene, int screen_size, float normal_offset_texels = 0.0f) const;

 private:
  const Context* context_;
  GlObject program_;
};

}  // namespace pn
