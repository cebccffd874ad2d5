#include "technique/cascaded_technique.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace pn {

TechniqueFrame CascadedTechnique::run(const TechniqueInputs& inputs, bool with_stats) const {
  if (!inputs.cascades) throw Error("a cascaded technique needs a cascaded frame (a scene lit by the sun)");
  const CascadeInputs& cascades = *inputs.cascades;
  std::vector<TechniqueFrame> layers;
  for (TechniqueInputs layer : cascades.layers) {
    layer.stage = inputs.stage;  // each cascade's call in the stage the frame asks for
    layers.push_back(inner_->run(layer, with_stats));
  }
  std::vector<const DeviceTexture*> visibilities;
  for (const TechniqueFrame& layer : layers) visibilities.push_back(layer.visibility.get());
  TechniqueFrame out;
  for (size_t c = 0; c < layers.size(); ++c) {
    for (const auto& stage : layers[c].stages) {  // not a structured binding: a lambda cannot capture one (C++17)
      const auto same = std::find_if(out.stages.begin(), out.stages.end(), [&](const auto& s) { return s.first == stage.first; });
      if (same == out.stages.end()) out.stages.push_back(stage);
      else same->second += stage.second;
    }
    for (const auto& [name, value] : layers[c].stats) out.stats.emplace_back("c" + std::to_string(c) + " " + name, value);
  }
  const std::unique_ptr<StageTimes> clock = device_->stage_clock();
  clock->start();
  out.visibility = blend_->blend(cascades, visibilities, inputs.screen_size);
  clock->stage("cascade blend");
  for (const auto& stage : clock->read()) out.stages.push_back(stage);
  return out;
}

}  // namespace pn
