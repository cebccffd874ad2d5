// One frame of a sun-lit scene on cascades (issue 14): the cascades fitted to
// the scene's camera (cascade_fit.h), each one's N×N map (ShadowMapRenderer
// with the cascade's light) and G-buffer (GBufferRenderer, only the surfaces in
// the cascade's fitted view-depth range), the camera's view depth, and the
// CascadeInputs that CascadedTechnique runs a technique on.
#pragma once

#include <memory>
#include <vector>

#include "cascades/cascade_fit.h"
#include "pass_runners/gbuffer_pass.h"
#include "pass_runners/second_layer_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "scene/scene.h"
#include "frame/technique.h"

namespace pn {

struct CascadedFrame {
  std::vector<Cascade> cascades;
  std::vector<MapLight> lights;     // each cascade's view, projection and light model
  std::vector<std::unique_ptr<DeviceTexture>> maps;      // N×N R32F linear light depth
  std::vector<std::unique_ptr<DeviceTexture>> gbuffers;  // screen² RGBA32F
  std::vector<SecondLayerTextures> second_layers;        // each cascade's, those asked for
  std::unique_ptr<DeviceTexture> view_depth;             // screen² RGBA32F: the camera's own G-buffer (z: view depth)
  CascadeInputs layers;             // points into the above: the frame is not copied or moved
  double shadow_map_ms = 0.0;       // every cascade's map, GPU time
  double second_layer_ms = 0.0;     // every cascade's second layers, GPU time (0: none drawn)
  int screen_size = 0;

  CascadedFrame() = default;
  CascadedFrame(const CascadedFrame&) = delete;
  CascadedFrame& operator=(const CascadedFrame&) = delete;

  // What CascadedTechnique::run takes: the scene's light, the screen, the layers.
  TechniqueInputs inputs(const LightModel& scene_light) const;
};

// The frustum a scene camera's cascades cover (square screen).
CascadeCamera cascade_camera(const SceneCamera& camera);

// A cascade's map light: its view and orthographic projection, and a light model with the
// sun's spread, the cascade's texel width and depth range, N = settings.map_size.
MapLight cascade_map_light(const Cascade& cascade, const SunLight& sun, int map_size);

// Throws Error for a scene without a sun, bad settings or a screen size outside 1..8192.
// `fit_camera`: the camera the cascades are fitted to, when it is not the scene's (which the
// G-buffers still see through): how bench cascades watches cascades move under a still view.
// `second_layers`: the second layers drawn beside each cascade's map.
std::unique_ptr<CascadedFrame> render_cascaded_frame(const QueryDevice& device, const ShadowMapRenderer& maps,
                                                     const GBufferRenderer& gbuffer, const Scene& scene,
                                                     const CascadeSettings& settings, int screen_size,
                                                     const SceneCamera* fit_camera = nullptr,
                                                     const SecondLayerRenderers* second_layers = nullptr);

}  // namespace pn
