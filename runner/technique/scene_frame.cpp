#include "technique/scene_frame.h"

#include <string>

#include "core/error.h"
#include "gl/gpu_timer.h"
#include "scenes.h"

namespace pn {

SceneFrame render_scene_frame(const Context& context, ShadowMapSource& source, const GBufferRenderer& gbuffer,
                              const Scene& scene, int screen_size) {
  if (screen_size < 1 || screen_size > 8192)
    throw Error("screen size " + std::to_string(screen_size) + ": expected 1..8192");
  SceneFrame frame;
  frame.light = scene.light;
  frame.screen_size = screen_size;
  StageClock clock(context);
  clock.start();
  frame.shadow_map = source.render(scene);
  clock.stage("shadow map");
  frame.shadow_map_ms = clock.read().front().second;
  frame.gbuffer = gbuffer.render(scene, screen_size, fixtures::kNormalOffsetTexels);
  return frame;
}

TechniqueMeasurement measure_technique(const Technique& technique, const TechniqueInputs& inputs, int repeats) {
  if (repeats < 1) throw Error("repeats " + std::to_string(repeats) + ": expected >= 1");
  technique.run(inputs, false);  // untimed warm-up
  std::vector<double> totals;
  std::vector<std::vector<double>> stages;
  TechniqueMeasurement m;
  for (int r = 0; r < repeats; ++r) {
    m.frame = technique.run(inputs, r + 1 == repeats);
    totals.push_back(m.frame.total_ms());
    stages.resize(m.frame.stages.size());
    for (size_t i = 0; i < m.frame.stages.size(); ++i) stages[i].push_back(m.frame.stages[i].second);
  }
  m.total_ms = median(totals);
  for (size_t i = 0; i < stages.size(); ++i) m.stage_ms.emplace_back(m.frame.stages[i].first, median(stages[i]));
  return m;
}

}  // namespace pn
