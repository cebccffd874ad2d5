// A shadow map's second layers (issue 42): what a frame draws beside its map for
// the techniques that read one (TechniqueConfig::second_layer) — the peeled
// layer (the nearest surface behind the map's) and the back-face layer (the
// nearest surface facing away from the light), each drawn whole through the
// map's light by ShadowMapRenderer, only when asked for.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "pass_runners/shadow_map_pass.h"

namespace pn {

// A frame's second layers, borrowed (null: not drawn).
struct SecondLayers {
  const DeviceTexture* peeled = nullptr;
  const DeviceTexture* back_faces = nullptr;
  const DeviceTexture* at(MapLayer layer) const {
    return layer == MapLayer::peeled ? peeled : layer == MapLayer::back_faces ? back_faces : nullptr;
  }
};

// The layers drawn for one map, owned.
struct SecondLayerTextures {
  std::unique_ptr<DeviceTexture> peeled, back_faces;
  SecondLayers view() const { return {peeled.get(), back_faces.get()}; }
};

class SecondLayerRenderers {
 public:
  // Programs for `layers` (each second layer at most once; MapLayer::first is ignored).
  SecondLayerRenderers(const QueryDevice& device, const SourceTree& tree, const std::vector<MapLayer>& layers);
  bool empty() const { return !peeled_ && !back_faces_; }
  // Each layer asked for, of `scene` through `light` (the light `first`, the map, was drawn through).
  SecondLayerTextures render(const Scene& scene, const MapLight& light, const DeviceTexture& first) const;

 private:
  std::optional<ShadowMapRenderer> peeled_, back_faces_;
};

}  // namespace pn
