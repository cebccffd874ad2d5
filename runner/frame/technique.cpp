#include "frame/technique.h"

namespace pn {

double TechniqueFrame::total_ms() const {
  double sum = 0.0;
  for (const auto& stage : stages) sum += stage.second;
  return sum;
}

std::vector<MapLayer> second_layers_of(const std::vector<const TechniqueConfig*>& configs) {
  std::vector<MapLayer> out;
  for (const MapLayer layer : {MapLayer::peeled, MapLayer::back_faces})
    for (const TechniqueConfig* config : configs)
      if (config->second_layer() == layer) {
        out.push_back(layer);
        break;
      }
  return out;
}

}  // namespace pn
