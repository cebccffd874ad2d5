#include "technique/shadow_map_sources.h"

#include "cache/depth_cache_source.h"
#include "cache/full_render_source.h"
#include "core/named.h"

namespace pn {

const std::vector<ShadowMapSourceEntry>& shadow_map_sources() {
  static const std::vector<ShadowMapSourceEntry> sources{
      {"full", "every triangle drawn into the map each frame",
       [](const QueryDevice& device, const SourceTree& tree, const SourceOptions& options) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<FullRenderSource>(device, tree, options);
       }},
      {"two-map", "seed 001: static map drawn again when an object starts or stops, dynamic map every frame",
       [](const QueryDevice& device, const SourceTree& tree, const SourceOptions& options) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<DepthCacheSource>(device, tree, CacheScheme::whole_maps, options);
       }},
      {"dirty-rect", "two maps, only their dirty rectangles drawn again; composition and structures updated there",
       [](const QueryDevice& device, const SourceTree& tree, const SourceOptions& options) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<DepthCacheSource>(device, tree, CacheScheme::dirty_rects, options);
       }},
  };
  return sources;
}

const ShadowMapSourceEntry& find_shadow_map_source(const std::string& name) {
  return find_named(shadow_map_sources(), name, "unknown shadow-map source '" + name + "'");
}

}  // namespace pn
