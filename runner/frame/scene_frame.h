// One frame of one scene as every technique reads it: the shadow map from a
// source, the G-buffer (Step 2) and the light; and the timed run of a
// technique over it (a warm-up, then medians of repeated runs).
#pragma once

#include <memory>

#include "pass_runners/gbuffer_pass.h"
#include "frame/shadow_map_source.h"
#include "frame/technique.h"

namespace pn {

// The map and its structures are the source's: valid until it renders again.
struct SceneFrame {
  LightModel light;
  int screen_size = 0;
  const DeviceTexture* shadow_map = nullptr;
  const MinMaxMipChain* mip = nullptr;    // when the source keeps them (SourceOptions)
  const DepthPyramid* pyramid = nullptr;
  std::unique_ptr<DeviceTexture> gbuffer;
  SecondLayerTextures second_layers;  // those asked for (render_scene_frame's `layers`)
  double shadow_map_ms = 0.0;  // the source's GPU time for this frame (not part of a technique's total)
  double second_layer_ms = 0.0;  // the second layers' GPU time (0: none drawn)

  TechniqueInputs inputs() const {
    TechniqueInputs in{light, screen_size, shadow_map, gbuffer.get(), mip, pyramid};
    in.second_layers = second_layers.view();
    return in;
  }
};

// Throws Error for a screen size outside 1..8192. The G-buffer's receivers
// are moved fixtures::kNormalOffsetTexels off their faces (gbuffer.frag). `layers`: the second
// layers drawn beside the source's map (whole, through the scene's light, whatever the source).
SceneFrame render_scene_frame(const QueryDevice& device, ShadowMapSource& source, const GBufferRenderer& gbuffer,
                              const Scene& scene, int screen_size, const SecondLayerRenderers* layers = nullptr);

// Repeated runs of one technique: the last frame (with stats), medians of the GPU times.
struct TechniqueMeasurement {
  TechniqueFrame frame;
  double total_ms = 0.0;
  NamedValues stage_ms;
};

// One untimed warm-up run of each (drivers compile shader variants on first use; llvmpipe ~1 s),
// then `repeats` >= 1 timed rounds, each running every technique once in turn — so a
// machine whose speed drifts during the run (a shared CPU) slows all of them alike,
// and the ratios between them hold. Throws Error for repeats < 1.
std::vector<TechniqueMeasurement> measure_techniques(const std::vector<const Technique*>& techniques,
                                                     const TechniqueInputs& inputs, int repeats);

}  // namespace pn
