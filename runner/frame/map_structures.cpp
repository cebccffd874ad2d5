#include "frame/map_structures.h"

#include "core/error.h"
#include "gl/texture.h"
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
    mip_builder_->build_into(map, mip_);
  }
  if (pyramid_builder_) {
    if (pyramid_.map_size != n) {
      pyramid_ = pyramid_builder_->build(map, n, n, options_.pyramid_max_level);
    } else {
      pyramid_builder_->build_into(map, pyramid_);
      pyramid_.level0 = texture_of_layer(*context_, pyramid_.texture, 0, n, n, 4);
    }
  }
}

void MapStructures::update(const GlObject& map, const std::vector<TexelRect>& rects) {
  if (rects.empty()) return;
  if (mip_builder_) mip_builder_->update_into(map, mip_, rects, texels_, options_.dilate_updates);
  if (pyramid_builder_) pyramid_builder_->update_into(map, pyramid_, rects, texels_, options_.dilate_updates);
}

}  // namespace pn
