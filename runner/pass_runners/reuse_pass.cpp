#include "pass_runners/reuse_pass.h"

#include "gl/std140.h"

namespace pn::glsl {
#include "passes/reuse_gather.h"
#include "passes/reuse_link.h"
PN_STD140_SIZE(PnReuseParams, 16);
PN_STD140_OFFSET(PnReuseParams, sigma3, 8);
PN_STD140_OFFSET(PnReuseParams, tile, 12);
PN_STD140_SIZE(PnReuseGatherParams, 16);
}  // namespace pn::glsl

namespace pn {

ReusePass::ReusePass(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      link_(device.compile_query(tree, "passes/reuse_link.comp", {})),
      gather_(device.compile_query(tree, "passes/reuse_gather.comp", {})) {}

std::unique_ptr<DeviceTexture> ReusePass::link(const DeviceTexture& entries, int width, int height,
                                               const ReuseParams& params) const {
  params.validate();
  std::unique_ptr<DeviceTexture> parents = device_->make_texture(float_shape(width, height, 1));
  const glsl::PnReuseParams block{params.sigma1, params.sigma2, params.sigma3, params.tile};
  device_->run(*link_,
               {{{PN_REUSE_LINK_ENTRIES_BINDING, entries}}, {{PN_REUSE_LINK_PARENTS_BINDING, *parents}}, {},
                query_block(block)},
               width, height);
  return parents;
}

std::unique_ptr<DeviceTexture> ReusePass::gather(const DeviceTexture& parents, const DeviceTexture& values, int width,
                                                 int height, int tile) const {
  std::unique_ptr<DeviceTexture> gathered = device_->make_texture(float_shape(width, height, 4));
  const glsl::PnReuseGatherParams block{tile};
  device_->run(*gather_,
               {{{PN_REUSE_GATHER_PARENTS_BINDING, parents}, {PN_REUSE_GATHER_VALUES_BINDING, values}},
                {{PN_REUSE_GATHER_RESULT_BINDING, *gathered}},
                {},
                query_block(block)},
               width, height);
  return gathered;
}

}  // namespace pn
