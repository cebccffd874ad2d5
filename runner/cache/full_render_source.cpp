#include "cache/full_render_source.h"

#include "gl/query_device_gl.h"

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
  map_ = std::make_unique<GlDeviceTexture>(target_->texture(), float_shape(n, n, 1));
  out_.map = map_.get();
  out_.mip = structures_.mip();
  out_.pyramid = structures_.pyramid();
  out_.changed = out_.redrawn = {TexelRect::square(n)};
  return out_;
}

}  // namespace pn
