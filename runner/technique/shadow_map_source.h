// Where a frame's shadow map comes from (SPEC §4.9): one interface, one entry
// per kind of source — a full render of the scene now; a static/dynamic cache
// (seed 001) and cascades (seed 003) later. Techniques never draw the map
// themselves, so any source serves any technique.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "passes/shadow_map_pass.h"
#include "scene/scene.h"

namespace pn {

class ShadowMapSource {
 public:
  virtual ~ShadowMapSource() = default;
  // This frame's map of `scene`: N×N R32F linear light depth, +Inf where
  // empty, N = scene.light.map_size. A source may keep state between frames.
  virtual GlObject render(const Scene& scene) = 0;
};

// Draws every triangle of the scene into a new map each frame.
class FullRenderSource : public ShadowMapSource {
 public:
  FullRenderSource(const Context& context, const SourceTree& tree) : renderer_(context, tree) {}
  GlObject render(const Scene& scene) override { return renderer_.render(scene); }

 private:
  ShadowMapRenderer renderer_;
};

struct ShadowMapSourceEntry {
  const char* name;
  const char* summary;
  std::unique_ptr<ShadowMapSource> (*make)(const Context& context, const SourceTree& tree);
};

const std::vector<ShadowMapSourceEntry>& shadow_map_sources();

// Throws Error naming `name` and listing the sources.
const ShadowMapSourceEntry& find_shadow_map_source(const std::string& name);

}  // namespace pn
