// The static/dynamic shadow-map caches (seed 001, issue 13), behind the
// ShadowMapSource interface: a static map of the objects that did not move,
// a dynamic map of those that did, their composition (depth_cache.glsl) the
// frame's map, and the map's structures kept beside it (map_structures.h).
//
//   whole_maps (the seed's scheme): the static map drawn again, whole, when
//     an object starts or stops moving; the dynamic map cleared and drawn
//     every frame; the composition and the structures over the whole map.
//   dirty_rects (beyond the seed): only the static map's dirty rectangles are
//     cleared and drawn again (scissored) — the map bounds of every object
//     that started moving (where it stood) or stopped (where it stands); the
//     dynamic map is cleared only over its objects' bounds, old and new,
//     before they are drawn; the composition and the structures are updated
//     over the tiles of all those rectangles.
// docs/modules/depth_cache.md has the rules and why they are exact.
#pragma once

#include <optional>
#include <vector>

#include "cache/map_structures.h"
#include "cache/object_motion.h"
#include "passes/depth_cache_pass.h"
#include "technique/shadow_map_source.h"

namespace pn {

enum class CacheScheme { whole_maps, dirty_rects };

// More static dirty rectangles than this (after merging overlaps) become their bounding rectangle:
// each is one scissored draw of every static object.
inline constexpr size_t kMaxStaticRects = 8;

class DepthCacheSource : public ShadowMapSource {
 public:
  DepthCacheSource(const Context& context, const SourceTree& tree, CacheScheme scheme, const SourceOptions& options = {});
  const SourcedMap& render(const Scene& scene) override;

  // The two maps as the last render left them (for the check).
  const GlObject& static_map() const { return static_->texture(); }
  const GlObject& dynamic_map() const { return dynamic_->texture(); }

 private:
  void draw_everything(const Scene& scene, const std::vector<VertexRun>& still, const std::vector<VertexRun>& moving);

  const Context* context_;
  CacheScheme scheme_;
  ShadowMapRenderer renderer_;
  DepthCacheComposer composer_;
  MapStructures structures_;
  ObjectMotion motion_;
  std::optional<SceneGeometry> geometry_;
  std::optional<RasterTarget> static_, dynamic_;
  GlObject composed_;
  TileList tiles_;
  SourcedMap out_;
};

}  // namespace pn
