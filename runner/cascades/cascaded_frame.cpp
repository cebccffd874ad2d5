#include "cascades/cascaded_frame.h"

#include <string>

#include "core/error.h"
#include "pass_runners/shadow_map_pass.h"
#include "scenes.h"

namespace pn {

TechniqueInputs CascadedFrame::inputs(const LightModel& scene_light) const {
  TechniqueInputs in;
  in.light = scene_light;
  in.screen_size = screen_size;
  in.cascades = &layers;
  return in;
}

CascadeCamera cascade_camera(const SceneCamera& camera) {
  CascadeCamera out;
  out.view = camera.view();
  out.fov_y_radians = camera.fov_degrees * 3.14159265358979 / 180.0;
  out.aspect = 1.0;
  out.near_plane = camera.near_plane;
  out.far_plane = camera.far_plane;
  return out;
}

MapLight cascade_map_light(const Cascade& cascade, const SunLight& sun, int map_size) {
  MapLight out;
  out.view = cascade.light_view;
  out.projection = cascade.light_projection;
  out.light.width = 0.0;
  out.light.spread = sun.spread();
  out.light.near_plane = cascade.depth_near;
  out.light.far_plane = cascade.depth_far;
  out.light.map_size = map_size;
  out.light.texel_world = cascade.texel_size;
  out.light.validate();
  return out;
}

std::unique_ptr<CascadedFrame> render_cascaded_frame(const QueryDevice& device, const ShadowMapRenderer& maps,
                                                     const GBufferRenderer& gbuffer, const Scene& scene,
                                                     const CascadeSettings& settings, int screen_size,
                                                     const SceneCamera* fit_camera,
                                                     const SecondLayerRenderers* second_layers) {
  if (!scene.sun) throw Error("scene '" + scene.name + "': cascades need a scene lit by the sun");
  if (screen_size < 1 || screen_size > 8192)
    throw Error("screen size " + std::to_string(screen_size) + ": expected 1..8192");
  const CascadeCamera camera = cascade_camera(fit_camera ? *fit_camera : scene.camera);
  const auto [lo, hi] = scene.bounds();
  auto frame = std::make_unique<CascadedFrame>();
  frame->screen_size = screen_size;
  frame->cascades = fit_cascades(settings, camera, scene.sun->direction, lo, hi);
  const std::unique_ptr<StageTimes> clock = device.stage_clock();
  clock->start();
  for (const Cascade& c : frame->cascades) {
    frame->lights.push_back(cascade_map_light(c, *scene.sun, settings.map_size));
    frame->maps.push_back(maps.render_texture(scene, frame->lights.back()));
  }
  clock->stage("cascade maps");
  if (second_layers != nullptr && !second_layers->empty()) {
    for (size_t i = 0; i < frame->cascades.size(); ++i)
      frame->second_layers.push_back(second_layers->render(scene, frame->lights[i], *frame->maps[i]));
    clock->stage("second layers");
  }
  const auto times = clock->read();
  frame->shadow_map_ms = times.front().second;
  if (times.size() > 1) frame->second_layer_ms = times[1].second;
  for (size_t i = 0; i < frame->cascades.size(); ++i)
    frame->gbuffers.push_back(gbuffer.render_texture(scene, screen_size, fixtures::kNormalOffsetTexels,
                                                     frame->lights[i], frame->cascades[i].fit_near,
                                                     frame->cascades[i].split_far));
  MapLight camera_light{scene.camera_view(), scene.camera_projection(), scene.light};
  frame->view_depth = gbuffer.render_texture(scene, screen_size, 0.0f, camera_light);
  CascadeInputs& layers = frame->layers;
  for (size_t i = 0; i < frame->cascades.size(); ++i) {
    TechniqueInputs layer;
    layer.light = frame->lights[i].light;
    layer.screen_size = screen_size;
    layer.shadow_map = frame->maps[i].get();
    layer.gbuffer = frame->gbuffers[i].get();
    if (i < frame->second_layers.size()) layer.second_layers = frame->second_layers[i].view();
    layers.layers.push_back(layer);
    layers.split_far[i] = frame->cascades[i].split_far;
  }
  layers.view_depth = frame->view_depth.get();
  layers.near = static_cast<float>(camera.near_plane);
  layers.band = static_cast<float>(settings.band);
  layers.fade_last = false;  // the camera's far plane ends the view: nothing to fade into
  return frame;
}

}  // namespace pn
