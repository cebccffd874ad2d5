#include "check/device_scene.h"

#include "pass_runners/gbuffer_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "scenes.h"

namespace pn {

DeviceSceneFrame render_device_frame(const CheckEnvironment& env, const Scene& scene, int screen_size,
                                     const std::vector<MapLayer>& layers) {
  DeviceSceneFrame frame;
  frame.shadow_map = ShadowMapRenderer(env.device, env.tree).render_texture(scene, scene.map_light());
  frame.gbuffer = GBufferRenderer(env.device, env.tree)
                      .render_texture(scene, screen_size, fixtures::kNormalOffsetTexels, scene.map_light());
  frame.inputs.light = scene.light;
  frame.inputs.screen_size = screen_size;
  frame.inputs.shadow_map = frame.shadow_map.get();
  frame.inputs.gbuffer = frame.gbuffer.get();
  if (!layers.empty()) {
    frame.second_layers =
        SecondLayerRenderers(env.device, env.tree, layers).render(scene, scene.map_light(), *frame.shadow_map);
    frame.inputs.second_layers = frame.second_layers.view();
  }
  return frame;
}

}  // namespace pn
