// Runner side of glsl/passes/hard_shadow.vert/.frag: the physical reference
// soft shadow — the average of many hard shadows from points spread over the
// area light (scene/light_samples.h) — that the techniques are measured against.
// Cost: samples_per_side^2 x (one shadow map + one camera pass), each a draw of
// every box; the running count ping-pongs between screen-sized R32F targets.
#pragma once

#include "gl/compute_program.h"
#include "passes/shadow_map_pass.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

class PhysicalReferenceRenderer {
 public:
  PhysicalReferenceRenderer(const Context& context, const SourceTree& tree);

  // R32F screen_size x screen_size texture, rows from the bottom like GBufferRenderer: per pixel the
  // fraction of the light's samples_per_side^2 sample points that see the surface point through the
  // pixel (nearest shadow-map texel of each sample point's own map, occluded when its depth <
  // receiver depth - bias); 1 where the pixel sees no surface. Each sample point's map has the
  // centre's orientation, projection and size (scene.light). Throws Error for samples_per_side
  // outside 1..64, screen_size < 1, or a bias that is negative or not finite.
  GlObject render(const Scene& scene, int screen_size, int samples_per_side, float bias) const;

 private:
  const Context* context_;
  ShadowMapRenderer shadow_map_;
  GlObject program_;
};

}  // namespace pn
