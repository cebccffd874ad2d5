// The structures a shadow-map source keeps beside its map for the techniques
// that read them (TechniqueInputs::mip, ::pyramid): Fast PCSS's min/max mip
// chain and the decreased pyramid, rebuilt whole or updated only where the
// map changed (a cache's dirty rectangles, MinMaxMipBuilder::update_into,
// DepthPyramidBuilder::update_into).
#pragma once

#include <optional>
#include <vector>

#include "core/texel_rect.h"
#include "device/texel_list.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/minmax_mip_pass.h"

namespace pn {

struct SourceOptions {
  bool mip_chain = false;      // keep the map's min/max mip chain
  int pyramid_max_level = -1;  // keep its pyramid up to this level (-1: none; 31: all)
  // false rounds the updates' rectangles in instead of dilating them: a broken cache, only for
  // showing that the check catches one.
  bool dilate_updates = true;
};

class MapStructures {
 public:
  MapStructures(const QueryDevice& device, const SourceTree& tree, const SourceOptions& options);
  // Every structure of the n×n map built again (allocated when n changes).
  void rebuild(const DeviceTexture& map, int n);
  // Only where the map changed since the last rebuild or update: `rects`.
  void update(const DeviceTexture& map, const std::vector<TexelRect>& rects);

  const MinMaxMipChain* mip() const { return mip_.texture ? &mip_ : nullptr; }
  const DepthPyramid* pyramid() const { return pyramid_.texture ? &pyramid_ : nullptr; }

 private:
  const QueryDevice* device_;
  SourceOptions options_;
  std::optional<MinMaxMipBuilder> mip_builder_;
  std::optional<DepthPyramidBuilder> pyramid_builder_;
  MinMaxMipChain mip_;
  DepthPyramid pyramid_;
  TexelList texels_;
};

}  // namespace pn
