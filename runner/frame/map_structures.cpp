#include "frame/map_structures.h"

#include "core/error.h"
#include "gl/query_device_gl.h"
#include "modules/depth_pyramid.h"

namespace pn {

MapStructures::MapStructures(const Context& context, const SourceTree& tree, const SourceOptions& options)
    : context_(&context), options_(options) {
  if (options.mip_chain) mip_builder_.emplace(context, tree);
  if (options.pyramid_max_level >= 0) pyramid_builder_.emplace(context, tree);
}

void MapStructures::rebuild(const GlObject& map, int n) {
  if (mip_builder_) {
    if (mip_.map_size != n) mip_ = mip_builder_->allocate(n);
    mip_builder_->build_into(GlDeviceTexture(map), mip_);
  }
  if (pyramid_builder_) {
    if (pyramid_.map_size != n) {
      pyramid_ = pyramid_builder_->build(GlDeviceTexture(map), n, n, options_.pyramid_max_level);
    } else {
      pyramid_builder_->build_into(GlDeviceTexture(map), pyramid_);
      pyramid_.level0 = context_->layer_texture(*pyramid_.texture, 0);
    }
  }
}

void MapStructures::update(const GlObject& map, const std::vector<TexelRect>& rects) {
  if (rects.empty()) return;
  if (mip_builder_) mip_builder_->update_into(GlDeviceTexture(map), mip_, rects, texels_, options_.dilate_updates);
  if (pyramid_builder_) pyramid_builder_->update_into(GlDeviceTexture(map), pyramid_, rects, texels_, options_.dilate_updates);
}

}  // namespace pn
