#include "frame/map_structures.h"

#include "core/error.h"
#include "modules/depth_pyramid_face.h"

namespace pn {

MapStructures::MapStructures(const QueryDevice& device, const SourceTree& tree, const SourceOptions& options)
    : device_(&device), options_(options) {
  if (options.mip_chain) mip_builder_.emplace(device, tree);
  if (options.pyramid_max_level >= 0) pyramid_builder_.emplace(device, tree);
}

void MapStructures::rebuild(const DeviceTexture& map, int n) {
  if (mip_builder_) {
    if (mip_.map_size != n) mip_ = mip_builder_->allocate(n);
    mip_builder_->build_into(map, mip_);
  }
  if (pyramid_builder_) {
    if (pyramid_.map_size != n) {
      pyramid_ = pyramid_builder_->build(map, n, n, options_.pyramid_max_level);
    } else {
      pyramid_builder_->build_into(map, pyramid_);
      pyramid_.level0 = device_->layer_texture(*pyramid_.texture, 0);
    }
  }
}

void MapStructures::update(const DeviceTexture& map, const std::vector<TexelRect>& rects) {
  if (rects.empty()) return;
  if (mip_builder_) mip_builder_->update_into(map, mip_, rects, texels_, options_.dilate_updates);
  if (pyramid_builder_) pyramid_builder_->update_into(map, pyramid_, rects, texels_, options_.dilate_updates);
}

}  // namespace pn
