#include "cache/full_render_source.h"

namespace pn {

FullRenderSource::FullRenderSource(const QueryDevice& device, const SourceTree& tree, const SourceOptions& options)
    : device_(&device), renderer_(device, tree), structures_(device, tree, options) {}

const SourcedMap& FullRenderSource::render(const Scene& scene) {
  const int n = scene.light.map_size;
  const std::vector<glm::vec3> vertices = scene.triangles();
  if (!geometry_ || geometry_->vertex_count() != static_cast<int>(vertices.size())) geometry_.emplace(*device_, scene);
  else geometry_->update_all(vertices);
  if (!target_ || target_->size() != n) target_ = device_->make_raster_target(n, TexelFormat::r32f);
  device_->clear_target(*target_, ShadowMapRenderer::far_clear());
  renderer_.draw(scene, *geometry_, *target_, {{0, geometry_->vertex_count()}});
  structures_.rebuild(target_->texture(), n);
  out_.map = &target_->texture();
  out_.mip = structures_.mip();
  out_.pyramid = structures_.pyramid();
  out_.changed = out_.redrawn = {TexelRect::square(n)};
  return out_;
}

}  // namespace pn
