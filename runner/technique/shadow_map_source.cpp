#include "technique/shadow_map_source.h"

#include "cache/depth_cache_source.h"
#include "core/error.h"

namespace pn {

FullRenderSource::FullRenderSource(const Context& context, const SourceTree& tree, const SourceOptions& options)
    : context_(&context), renderer_(context, tree), structures_(context, tree, options) {}

const SourcedMap& FullRenderSource::render(const Scene& scene) {
  const int n = scene.light.map_size;
  const std::vector<glm::vec3> vertices = scene.triangles();
  if (!geometry_ || geometry_->vertex_count() != static_cast<int>(vertices.size())) geometry_.emplace(*context_, scene);
  else geometry_->update_all(vertices);
  if (!target_ || target_->size() != n) target_.emplace(*context_, n, 1);
  target_->clear(ShadowMapRenderer::far_clear());
  renderer_.draw(scene, *geometry_, *target_, {{0, geometry_->vertex_count()}});
  structures_.rebuild(target_->texture(), n);
  out_.map = &target_->texture();
  out_.mip = structures_.mip();
  out_.pyramid = structures_.pyramid();
  out_.changed = out_.redrawn = {TexelRect::square(n)};
  return out_;
}

const std::vector<ShadowMapSourceEntry>& shadow_map_sources() {
  static const std::vector<ShadowMapSourceEntry> sources{
      {"full", "every triangle drawn into the map each frame",
       [](const Context& context, const SourceTree& tree, const SourceOptions& options) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<FullRenderSource>(context, tree, options);
       }},
      {"two-map", "seed 001: static map drawn again when an object starts or stops, dynamic map every frame",
       [](const Context& context, const SourceTree& tree, const SourceOptions& options) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<DepthCacheSource>(context, tree, CacheScheme::whole_maps, options);
       }},
      {"dirty-rect", "two maps, only their dirty rectangles drawn again; composition and structures updated there",
       [](const Context& context, const SourceTree& tree, const SourceOptions& options) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<DepthCacheSource>(context, tree, CacheScheme::dirty_rects, options);
       }},
  };
  return sources;
}

const ShadowMapSourceEntry& find_shadow_map_source(const std::string& name) {
  std::string known;
  for (const ShadowMapSourceEntry& e : shadow_map_sources()) {
    if (name == e.name) return e;
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  throw Error("unknown shadow-map source '" + name + "': expected one of " + known);
}

}  // namespace pn
