#include "cache/depth_cache_source.h"

#include <algorithm>


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

DepthCacheSource::DepthCacheSource(const QueryDevice& device, const SourceTree& tree, CacheScheme scheme,
                                   const SourceOptions& options)
    : device_(&device), scheme_(scheme), renderer_(device, tree), composer_(device, tree),
      structures_(device, tree, options) {}

void DepthCacheSource::compose_whole(const Scene& scene, const std::vector<VertexRun>& moving) {
  const int n = scene.light.map_size;
  if (scheme_ == CacheScheme::whole_maps) {
    device_->clear_target(*dynamic_, ShadowMapRenderer::far_clear());
    if (!moving.empty()) renderer_.draw(scene, *geometry_, *dynamic_, moving);
    composer_.compose(static_->texture(), dynamic_->texture(), composed_->texture(), n);
  } else {
    device_->copy_target(*static_, *composed_);
    if (!moving.empty()) renderer_.draw(scene, *geometry_, *composed_, moving);
  }
  structures_.rebuild(composed_->texture(), n);
  out_.changed = {TexelRect::square(n)};
}

const SourcedMap& DepthCacheSource::render(const Scene& scene) {
  const int n = scene.light.map_size;
  const std::vector<glm::vec3> vertices = scene.triangles();
  const bool continues = motion_.track(scene, vertices);
  const std::vector<ObjectFrame>& objects = motion_.objects();
  const std::vector<SceneObject>& layout = motion_.layout();
  const std::vector<VertexRun> still = runs_of(layout, [&](size_t i) { return !objects[i].dynamic; });
  const std::vector<VertexRun> moving = runs_of(layout, [&](size_t i) { return objects[i].dynamic; });
  const TexelRect whole = TexelRect::square(n);

  if (!continues) {  // a new scene (or the first frame): everything drawn
    geometry_.emplace(*device_, scene);
    static_ = device_->make_raster_target(n, TexelFormat::r32f);
    if (scheme_ == CacheScheme::whole_maps) dynamic_ = device_->make_raster_target(n, TexelFormat::r32f);
    composed_ = device_->make_raster_target(n, TexelFormat::r32f);
    device_->clear_target(*static_, ShadowMapRenderer::far_clear());
    renderer_.draw(scene, *geometry_, *static_, still);
    compose_whole(scene, moving);
    out_.redrawn = {whole};
  } else {
    std::vector<int> moved;
    bool state_changed = false;
    for (size_t i = 0; i < objects.size(); ++i) {
      if (objects[i].dynamic) moved.push_back(static_cast<int>(i));
      state_changed = state_changed || objects[i].dynamic != objects[i].was_dynamic;
    }
    geometry_->update(vertices, layout, moved);

    if (scheme_ == CacheScheme::whole_maps) {
      out_.redrawn.clear();
      if (state_changed) {
        device_->clear_target(*static_, ShadowMapRenderer::far_clear());
        renderer_.draw(scene, *geometry_, *static_, still);
        out_.redrawn = {whole};
      } else {  // only the moving objects were drawn, into the dynamic map
        for (const ObjectFrame& o : objects)
          if (o.dynamic) out_.redrawn.push_back(o.bounds);
      }
      compose_whole(scene, moving);
    } else {
      // The static map changes where an object left it (started moving: its old place) or joined
      // it (stopped: where it stands, its bounds unchanged since the frame it stopped in); the
      // frame's map also where a moving object was and is.
      std::vector<TexelRect> static_rects, changed;
      for (const ObjectFrame& o : objects) {
        if (o.dynamic && !o.was_dynamic) static_rects.push_back(o.old_bounds);
        if (!o.dynamic && o.was_dynamic) static_rects.push_back(o.bounds);
        // One rectangle for both: an object moves little in a frame, so the two overlap mostly.
        const TexelRect both = bounding(o.was_dynamic ? o.old_bounds : TexelRect{}, o.dynamic ? o.bounds : TexelRect{});
        if (!both.empty()) changed.push_back(both);
      }
      static_rects = merged_rects(static_rects, kMaxStaticRects);
      if (!static_rects.empty()) {
        device_->clear_target(*static_, ShadowMapRenderer::far_clear(), static_rects);
        renderer_.draw(scene, *geometry_, *static_, still, static_rects);
      }
      // Not merged: a merge of overlapping rectangles into their bounds grows with every object it
      // takes in, and a texel that two rectangles hold is merely copied and computed twice.
      changed.insert(changed.end(), static_rects.begin(), static_rects.end());
      out_.redrawn = out_.changed = changed;
      if (static_cast<double>(total_area(changed)) >= kWholeFrameShare * n * n) {
        // Most of the map changed: drawn whole, as the full render draws it.
        device_->clear_target(*composed_, ShadowMapRenderer::far_clear());
        renderer_.draw(scene, *geometry_, *composed_, {{0, geometry_->vertex_count()}});
        structures_.rebuild(composed_->texture(), n);
        out_.changed = out_.redrawn = {whole};
      } else if (!changed.empty()) {
        // The static map's colour and depth where anything changed, then the moving objects drawn
        // over it with the depth test: every texel they cover lies in their bounds, copied afresh.
        device_->copy_target(*static_, *composed_, changed);
        if (!moving.empty()) renderer_.draw(scene, *geometry_, *composed_, moving);
        structures_.update(composed_->texture(), changed);
      }
    }
  }
  out_.map = &composed_->texture();
  out_.mip = structures_.mip();
  out_.pyramid = structures_.pyramid();
  return out_;
}

}  // namespace pn
