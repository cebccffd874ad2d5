#include "pass_runners/cascade_blend_pass.h"

#include <string>

#include "core/error.h"
#include "gl/query_device_gl.h"
#include "gl/std140.h"

namespace pn::glsl {
#include "passes/cascade_blend.h"
PN_STD140_SIZE(PnCascadeBlendParams, 32);
PN_STD140_OFFSET(PnCascadeBlendParams, near, 16);
PN_STD140_OFFSET(PnCascadeBlendParams, fadeLast, 28);
}  // namespace pn::glsl

namespace pn {

CascadeBlendPass::CascadeBlendPass(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_query(tree, "passes/cascade_blend.comp", {})),
      unused_(device.make_texture(float_shape(1, 1, 1))) {}

std::unique_ptr<DeviceTexture> CascadeBlendPass::blend(const DeviceTexture& view_depth, const CascadeBlend& cascades,
                                                       const std::vector<const DeviceTexture*>& visibilities,
                                                       int screen_size) const {
  const size_t count = visibilities.size();
  if (count < 1 || count > 4)
    throw Error("cascade blend: " + std::to_string(count) + " visibilities: expected one a cascade, 1 ... 4");
  glsl::PnCascadeBlendParams block{};
  block.splitFar = {cascades.split_far[0], cascades.split_far[1], cascades.split_far[2], cascades.split_far[3]};
  block.near = cascades.near;
  block.count = static_cast<int>(count);
  block.band = cascades.band;
  block.fadeLast = cascades.fade_last ? 1 : 0;
  std::unique_ptr<DeviceTexture> target = device_->make_texture(float_shape(screen_size, screen_size, 1));
  PassResources resources{{{PN_CASCADE_BLEND_VIEW_DEPTH_BINDING, view_depth}},
                          {{PN_CASCADE_BLEND_TARGET_BINDING, *target}},
                          {},
                          query_block(block)};
  const unsigned slots[4] = {PN_CASCADE_BLEND_VISIBILITY0_BINDING, PN_CASCADE_BLEND_VISIBILITY1_BINDING,
                             PN_CASCADE_BLEND_VISIBILITY2_BINDING, PN_CASCADE_BLEND_VISIBILITY3_BINDING};
  for (size_t c = 0; c < 4; ++c) resources.textures.push_back({slots[c], c < count ? *visibilities[c] : *unused_});
  device_->run(*program_, resources, screen_size, screen_size);
  return target;
}

std::unique_ptr<DeviceTexture> CascadeBlendPass::blend(const CascadeBlend& cascades,
                                                       const std::vector<const DeviceTexture*>& visibilities,
                                                       int screen_size) const {
  if (!cascades.view_depth) throw Error("cascade blend: expected the camera's view depth");
  return blend(*cascades.view_depth, cascades, visibilities, screen_size);
}

}  // namespace pn
