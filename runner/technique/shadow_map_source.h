// Where a frame's shadow map comes from (SPEC §4.9): one interface, one entry
// per kind of source — a full render of the scene, the static/dynamic caches
// of seed 001 (runner/cache/), cascades (seed 003) later. Techniques never
// draw the map themselves, so any source serves any technique.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cache/map_structures.h"
#include "core/texel_rect.h"
#include "gl/objects.h"
#include "passes/shadow_map_pass.h"
#include "scene/scene.h"

namespace pn {

// What a source hands a frame, borrowed from the source: valid until its next render.
struct SourcedMap {
  const GlObject* map = nullptr;          // N×N R32F linear light depth, +Inf where empty, N = scene.light.map_size
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

// Draws every triangle of the scene into the map each frame (the map, its depth buffer and the
// vertex buffer kept between frames, every vertex written again), and rebuilds the structures.
class FullRenderSource : public ShadowMapSource {
 public:
  FullRenderSource(const Context& context, const SourceTree& tree, const SourceOptions& options = {});
  const SourcedMap& render(const Scene& scene) override;

 private:
  const Context* context_;
  ShadowMapRenderer renderer_;
  MapStructures structures_;
  std::optional<SceneGeometry> geometry_;
  std::optional<RasterTarget> target_;
  SourcedMap out_;
};

struct ShadowMapSourceEntry {
  const char* name;
  const char* summary;
  std::unique_ptr<ShadowMapSource> (*make)(const Context& context, const SourceTree& tree, const SourceOptions& options);
};

const std::vector<ShadowMapSourceEntry>& shadow_map_sources();

// Throws Error naming `name` and listing the sources.
const ShadowMapSourceEntry& find_shadow_map_source(const std::string& name);

}  // namespace pn
