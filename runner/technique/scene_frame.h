// One frame of one scene as every technique reads it: the shadow map from a
// source, the G-buffer (Step 2) and the light; and the timed run of a
// technique over it (a warm-up, then medians of repeated runs).
#pragma once

#include "passes/gbuffer_pass.h"
#include "technique/shadow_map_source.h"
#include "technique/technique.h"

namespace pn {

struct SceneFrame {
  LightModel light;
  int screen_size = 0;
  GlObject shadow_map;
  GlObject gbuffer;
  double shadow_map_ms = 0.0;  // the source's GPU time for this frame (not part of a technique's total)

  TechniqueInputs inputs() const { return {light, screen_size, &shadow_map, &gbuffer}; }
};

// Throws Error for a screen size outside 1..8192. The G-buffer's receivers
// are moved fixtures::kNormalOffsetTexels off their faces (gbuffer.frag).
SceneFrame render_scene_frame(const Context& context, ShadowMapSource& source, const GBufferRenderer& gbuffer,
                              const Scene& scene, int screen_size);

// Repeated runs of one technique: the last frame (with stats), medians of the GPU times.
struct TechniqueMeasurement {
  TechniqueFrame frame;
  double total_ms = 0.0;
  NamedValues stage_ms;
};

// One untimed warm-up run (drivers compile shader variants on first use; llvmpipe ~1 s),
// then `repeats` >= 1 timed runs. Throws Error for repeats < 1.
TechniqueMeasurement measure_technique(const Technique& technique, const TechniqueInputs& inputs, int repeats);

}  // namespace pn
