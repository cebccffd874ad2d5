#include "frame/scene_frame.h"

#include <string>

#include "core/error.h"
#include "gl/gpu_timer.h"
#include "scenes.h"

namespace pn {

SceneFrame render_scene_frame(const QueryDevice& device, ShadowMapSource& source, const GBufferRenderer& gbuffer,
                              const Scene& scene, int screen_size, const SecondLayerRenderers* layers) {
  if (screen_size < 1 || screen_size > 8192)
    throw Error("screen size " + std::to_string(screen_size) + ": expected 1..8192");
  SceneFrame frame;
  frame.light = scene.light;
  frame.screen_size = screen_size;
  const std::unique_ptr<StageTimes> clock = device.stage_clock();
  clock->start();
  const SourcedMap& sourced = source.render(scene);
  clock->stage("shadow map");
  frame.shadow_map = sourced.map;
  frame.mip = sourced.mip;
  frame.pyramid = sourced.pyramid;
  if (layers != nullptr && !layers->empty()) {
    frame.second_layers = layers->render(scene, scene.map_light(), *sourced.map);
    clock->stage("second layers");
  }
  const NamedValues times = clock->read();
  frame.shadow_map_ms = times.front().second;
  if (times.size() > 1) frame.second_layer_ms = times[1].second;
  frame.gbuffer = gbuffer.render_texture(scene, screen_size, fixtures::kNormalOffsetTexels, scene.map_light());
  return frame;
}

std::vector<TechniqueMeasurement> measure_techniques(const std::vector<const Technique*>& techniques,
                                                     const TechniqueInputs& inputs, int repeats) {
  if (repeats < 1) throw Error("repeats " + std::to_string(repeats) + ": expected >= 1");
  for (const Technique* t : techniques) t->run(inputs, false);  // untimed warm-ups
  const size_t n = techniques.size();
  std::vector<std::vector<double>> totals(n);
  std::vector<std::vector<std::vector<double>>> stages(n);
  std::vector<TechniqueMeasurement> out(n);
  for (int r = 0; r < repeats; ++r)
    for (size_t k = 0; k < n; ++k) {
      TechniqueMeasurement& m = out[k];
      m.frame = techniques[k]->run(inputs, r + 1 == repeats);
      totals[k].push_back(m.frame.total_ms());
      stages[k].resize(m.frame.stages.size());
      for (size_t i = 0; i < m.frame.stages.size(); ++i) stages[k][i].push_back(m.frame.stages[i].second);
    }
  for (size_t k = 0; k < n; ++k) {
    out[k].total_ms = median(totals[k]);
    for (size_t i = 0; i < stages[k].size(); ++i)
      out[k].stage_ms.emplace_back(out[k].frame.stages[i].first, median(stages[k][i]));
  }
  return out;
}

}  // namespace pn
