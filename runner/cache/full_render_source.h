// The simplest shadow-map source: every triangle drawn into the map each frame.
#pragma once

#include <memory>
#include <optional>

#include "frame/shadow_map_source.h"
#include "pass_runners/shadow_map_pass.h"

namespace pn {

// Draws every triangle of the scene into the map each frame (the map, its depth buffer and the
// vertex buffer kept between frames, every vertex written again), and rebuilds the structures.
class FullRenderSource : public ShadowMapSource {
 public:
  FullRenderSource(const QueryDevice& device, const SourceTree& tree, const SourceOptions& options = {});
  const SourcedMap& render(const Scene& scene) override;

 private:
  const QueryDevice* device_;
  ShadowMapRenderer renderer_;
  MapStructures structures_;
  std::optional<SceneGeometry> geometry_;
  std::unique_ptr<DeviceRasterTarget> target_;
  SourcedMap out_;
};

}  // namespace pn
