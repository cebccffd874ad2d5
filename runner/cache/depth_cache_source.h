// The static/dynamic shadow-map caches (seed 001, issue 13), behind the
// ShadowMapSource interface: a static map of the objects that did not move,
// the frame's map made from it and the objects that moved, and the map's
// structures kept beside it (map_structures.h).
//
//   whole_maps (the seed's scheme): the static map drawn again, whole, when
//     an object starts or stops moving; a dynamic map of the moving objects
//     cleared and drawn every frame; the frame's map their composition
//     min(static, dynamic) (depth_cache.glsl), and the structures rebuilt,
//     every frame.
//   dirty_rects (beyond the seed): only the static map's dirty rectangles are
//     cleared and drawn again (scissored) — the map bounds of every object
//     that started moving (where it stood) or stopped (where it stands). The
//     frame's map changes only there and in the bounds, old and new, of every
//     moving object: the static map's colour and depth are copied into those
//     rectangles and the moving objects drawn over them with the depth test
//     (the full render's own rule for the nearest surface); the structures
//     are updated over the same rectangles. When those cover kWholeFrameShare
//     of the map or more, the frame's map is drawn whole instead (every
//     triangle, as the full render) and the structures rebuilt.
// docs/modules/depth_cache.md has the rules and why they are exact.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "frame/map_structures.h"
#include "cache/object_motion.h"
#include "pass_runners/depth_cache_pass.h"
#include "frame/shadow_map_source.h"
#include "pass_runners/shadow_map_pass.h"

namespace pn {

enum class CacheScheme { whole_maps, dirty_rects };

// More static dirty rectangles than this (after merging overlaps) become their bounding rectangle:
// each is one scissored draw of every static object.
inline constexpr size_t kMaxStaticRects = 8;
// A frame whose changed rectangles cover this share of the map or more is drawn whole.
inline constexpr double kWholeFrameShare = 0.75;

class DepthCacheSource : public ShadowMapSource {
 public:
  DepthCacheSource(const QueryDevice& device, const SourceTree& tree, CacheScheme scheme,
                   const SourceOptions& options = {});
  const SourcedMap& render(const Scene& scene) override;

 private:
  // The frame's map from the static map and the moving objects, everywhere; the structures rebuilt.
  void compose_whole(const Scene& scene, const std::vector<VertexRun>& moving);

  const QueryDevice* device_;
  CacheScheme scheme_;
  ShadowMapRenderer renderer_;
  DepthCacheComposer composer_;
  MapStructures structures_;
  ObjectMotion motion_;
  std::optional<SceneGeometry> geometry_;
  std::unique_ptr<DeviceRasterTarget> static_, dynamic_, composed_;  // dynamic_: whole_maps only
  SourcedMap out_;
};

}  // namespace pn
