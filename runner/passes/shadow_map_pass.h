// Runner side of glsl/passes/shadow_depth.vert/.frag: renders a scene's
// shadow map of linear light depth (SPEC §4.7 Step 1) into an R32F texture,
// +Inf where no surface is seen (SPEC §3: no occluder).
#pragma once

#include "gl/compute_program.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

class ShadowMapRenderer {
 public:
  ShadowMapRenderer(const Context& context, const SourceTree& tree);

  // N×N R32F texture, N = scene.light.map_size; rows from the framebuffer's bottom.
  GlObject render(const Scene& scene) const;

 private:
  const Context* context_;
  GlObject program_;
};

}  // namespace pn
