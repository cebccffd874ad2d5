#include "cache/depth_cache_source.h"

#include <algorithm>

#include "gl/texture.h"

namespace pn {
namespace {

// The vertex runs of the objects for which `take` holds, neighbours joined into one run.
template <class Take>
std::vector<VertexRun> runs_of(const std::vector<SceneObject>& objects, const Take& take) {
  std::vector<VertexRun> runs;
  for (size_t i = 0; i < objects.size(); ++i) {
    if (!take(i)) continue;
    const SceneObject& o = objects[i];
    if (!runs.empty() && runs.back().first + runs.back().count == o.first_vertex) runs.back().count += o.vertex_count;
    else runs.push_back({o.first_vertex, o.vertex_count});
  }
  return runs;
}

}  // namespace

DepthCacheSource::DepthCacheSource(const Context& context, const SourceTree& tree, CacheScheme scheme,
                                   const SourceOptions& options)
    : context_(&context), scheme_(scheme), renderer_(context, tree), composer_(context, tree),
      structures_(context, tree, options) {}

void DepthCacheSource::draw_everything(const Scene& scene, const std::vector<VertexRun>& still,
                                       const std::vector<VertexRun>& moving) {
  const int n = scene.light.map_size;
  static_->clear(ShadowMapRenderer::far_clear());
  renderer_.draw(scene, *geometry_, *static_, still);
  dynamic_->clear(ShadowMapRenderer::far_clear());
  renderer_.draw(scene, *geometry_, *dynamic_, moving);
  composer_.compose(static_->texture(), dynamic_->texture(), composed_, n);
  structures_.rebuild(composed_, n);
  out_.changed = out_.redrawn = {TexelRect::square(n)};
}

const SourcedMap& DepthCacheSource::render(const Scene& scene) {
  const int n = scene.light.map_size;
  const std::vector<glm::vec3> vertices = scene.triangles();
  const bool continues = motion_.track(scene, vertices);
  const std::vector<ObjectFrame>& objects = motion_.objects();
  const std::vector<SceneObject>& layout = motion_.layout();
  const auto moved = [&](size_t i) { return objects[i].dynamic; };
  const auto still = [&](size_t i) { return !objects[i].dynamic; };
  const std::vector<VertexRun> still_runs = runs_of(layout, still), moving_runs = runs_of(layout, moved);

  if (!continues) {  // a new scene (or the first frame): everything drawn
    geometry_.emplace(*context_, scene);
    static_.emplace(*context_, n, 1);
    dynamic_.emplace(*context_, n, 1);
    composed_ = make_float_texture(*context_, n, n, 1);
    draw_everything(scene, still_runs, moving_runs);
  } else {
    std::vector<int> moved_objects;
    bool state_changed = false;
    for (size_t i = 0; i < objects.size(); ++i) {
      if (objects[i].dynamic) moved_objects.push_back(static_cast<int>(i));
      state_changed = state_changed || objects[i].dynamic != objects[i].was_dynamic;
    }
    geometry_->update(vertices, layout, moved_objects);

    if (scheme_ == CacheScheme::whole_maps) {
      if (state_changed) {
        static_->clear(ShadowMapRenderer::far_clear());
        renderer_.draw(scene, *geometry_, *static_, still_runs);
      }
      dynamic_->clear(ShadowMapRenderer::far_clear());
      renderer_.draw(scene, *geometry_, *dynamic_, moving_runs);
      composer_.compose(static_->texture(), dynamic_->texture(), composed_, n);
      structures_.rebuild(composed_, n);
      out_.changed = out_.redrawn = {TexelRect::square(n)};
    } else {
      // The static map changes where an object left it (started moving: its old place) or joined
      // it (stopped: where it stands, its bounds unchanged since the frame it stopped in).
      std::vector<TexelRect> static_rects, dynamic_rects;
      for (const ObjectFrame& o : objects) {
        if (o.dynamic && !o.was_dynamic) static_rects.push_back(o.old_bounds);
        if (!o.dynamic && o.was_dynamic) static_rects.push_back(o.bounds);
        // The dynamic map changes where a moving object was and where it is.
        if (o.dynamic || o.was_dynamic)
          dynamic_rects.push_back(bounding(o.was_dynamic ? o.old_bounds : TexelRect{}, o.dynamic ? o.bounds : TexelRect{}));
      }
      static_rects = merged_rects(static_rects, kMaxStaticRects);
      if (!static_rects.empty()) {
        static_->clear(ShadowMapRenderer::far_clear(), static_rects);
        renderer_.draw(scene, *geometry_, *static_, still_runs, static_rects);
      }
      // Every texel a moving object covers lies in its cleared bounds: drawn unscissored.
      dynamic_rects.erase(std::remove_if(dynamic_rects.begin(), dynamic_rects.end(),
                                         [](const TexelRect& r) { return r.empty(); }),
                          dynamic_rects.end());
      if (!dynamic_rects.empty()) dynamic_->clear(ShadowMapRenderer::far_clear(), dynamic_rects);
      if (!moving_runs.empty()) renderer_.draw(scene, *geometry_, *dynamic_, moving_runs);

      out_.changed = static_rects;
      out_.changed.insert(out_.changed.end(), dynamic_rects.begin(), dynamic_rects.end());
      out_.redrawn = out_.changed;
      if (!out_.changed.empty()) {
        tiles_.clear();
        const TileRun run = tiles_.add(out_.changed, n, n);
        tiles_.upload(*context_);
        composer_.compose(static_->texture(), dynamic_->texture(), composed_, n, run, &tiles_);
        structures_.update(composed_, out_.changed);
      }
    }
  }
  out_.map = &composed_;
  out_.mip = structures_.mip();
  out_.pyramid = structures_.pyramid();
  return out_;
}

}  // namespace pn
