// A scene's shadow map and G-buffer rendered on the check's executor (GL, Vulkan, HLSL), as a
// frame renders them (frame/scene_frame.h's render_scene_frame: the full render, the G-buffer's
// normal offset), and the pipeline's inputs over them.
#pragma once

#include <memory>

#include "check/module_check.h"
#include "pipeline/pcss_pipeline.h"
#include "scene/scene.h"

namespace pn {

struct DeviceSceneFrame {
  std::unique_ptr<DeviceTexture> shadow_map;  // N×N R32F
  std::unique_ptr<DeviceTexture> gbuffer;     // screen² RGBA32F
  SecondLayerTextures second_layers;          // those asked for
  TechniqueInputs inputs;                     // all of them, the scene's light, the screen size
};

// `layers`: the map's second layers to draw beside it (the ones techniques ask for).
DeviceSceneFrame render_device_frame(const CheckEnvironment& env, const Scene& scene, int screen_size,
                                     const std::vector<MapLayer>& layers = {});

}  // namespace pn
