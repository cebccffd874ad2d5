#include "pass_runners/second_layer_pass.h"

#include <algorithm>

namespace pn {

SecondLayerRenderers::SecondLayerRenderers(const QueryDevice& device, const SourceTree& tree,
                                           const std::vector<MapLayer>& layers) {
  const auto asked = [&](MapLayer layer) { return std::find(layers.begin(), layers.end(), layer) != layers.end(); };
  if (asked(MapLayer::peeled)) peeled_.emplace(device, tree, MapLayer::peeled);
  if (asked(MapLayer::back_faces)) back_faces_.emplace(device, tree, MapLayer::back_faces);
}

SecondLayerTextures SecondLayerRenderers::render(const Scene& scene, const MapLight& light,
                                                 const DeviceTexture& first) const {
  SecondLayerTextures out;
  if (peeled_) out.peeled = peeled_->render_texture(scene, light, &first);
  if (back_faces_) out.back_faces = back_faces_->render_texture(scene, light);
  return out;
}

}  // namespace pn
