// Where a frame's shadow map comes from (SPEC §4.9): one interface, one entry
// per kind of source in the catalogue (technique/shadow_map_sources.h) — a
// full render of the scene, the static/dynamic caches of seed 001 (cache/).
// Techniques never draw the map themselves, so any source serves any technique.
#pragma once

#include <vector>

#include "core/texel_rect.h"
#include "frame/map_structures.h"
#include "device/query_device.h"
#include "scene/scene.h"

namespace pn {

// What a source hands a frame, borrowed from the source: valid until its next render.
struct SourcedMap {
  const DeviceTexture* map = nullptr;     // N×N R32F linear light depth, +Inf where empty, N = scene.light.map_size
  const MinMaxMipChain* mip = nullptr;    // the map's structures when the source keeps them (SourceOptions), else null
  const DepthPyramid* pyramid = nullptr;
  std::vector<TexelRect> changed;         // where the map may differ from the previous frame's (the whole map: anywhere)
  std::vector<TexelRect> redrawn;         // where triangles were drawn this frame (static and dynamic maps)
};

class ShadowMapSource {
 public:
  virtual ~ShadowMapSource() = default;
  // This frame's map of `scene`. A source may keep state between frames (a cache compares
  // Scene::objects' transforms with the previous frame's).
  virtual const SourcedMap& render(const Scene& scene) = 0;
};

}  // namespace pn
