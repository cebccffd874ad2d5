#include "pass_runners/blur_pass.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "gl/std140.h"

namespace pn::glsl {
#include "passes/blur_bindings.h"
PN_STD140_SIZE(PnBlurPassParams, 32);
PN_STD140_OFFSET(PnBlurPassParams, radius, 8);
PN_STD140_OFFSET(PnBlurPassParams, depthTolerance, 20);
PN_STD140_OFFSET(PnBlurPassParams, pixelsPerTexel, 28);
}  // namespace pn::glsl

namespace pn {

BlurPass::BlurPass(const QueryDevice& device, const SourceTree& tree)
    : device_(&device), variants_(device, tree, "passes/blur.comp") {
  for (int v = 0; v < 4; ++v) {  // the single-channel variants now, so a copy that does not compile fails here
    BlurParams params;
    params.depth_aware = (v & 2) != 0;
    params.adaptive = (v & 1) != 0;
    program(params, 1);
  }
}

const QueryProgram& BlurPass::program(const BlurParams& params, int channels) const {
  const auto truth = [](bool b) { return std::string(b ? "true" : "false"); };
  const std::vector<Define> defines{{"PN_BLUR_PASS_DEPTH_AWARE", truth(params.depth_aware)},
                                    {"PN_BLUR_PASS_ADAPTIVE", truth(params.adaptive)},
                                    {"PN_BLUR_PASS_CHANNELS", std::to_string(channels)}};
  return variants_.get(defines);
}

std::unique_ptr<DeviceTexture> BlurPass::run(const DeviceTexture& source, const DeviceTexture* depth, int width,
                                             int height, const BlurParams& params, const DeviceTexture* filter_map,
                                             int channels) const {
  params.validate();
  if (channels != 1 && channels != 2 && channels != 4)
    throw Error("blur: " + std::to_string(channels) + " channels: expected 1, 2 or 4");
  if (params.adaptive && filter_map == nullptr)
    throw Error("blur: the adaptive radius needs the filter-region map (none given)");
  const QueryProgram& pass = program(params, channels);
  const TextureShape shape = float_shape(width, height, device_->storage_channels(channels));
  const std::unique_ptr<DeviceTexture> temporary = device_->make_texture(shape);
  std::unique_ptr<DeviceTexture> target = device_->make_texture(shape);

  auto one_pass = [&](const DeviceTexture& in, const DeviceTexture& out, int ax, int ay) {
    const glsl::PnBlurPassParams block{{ax, ay},
                                       params.radius,
                                       static_cast<float>(params.sigma),
                                       params.depth_aware ? 1 : 0,
                                       static_cast<float>(params.depth_tolerance),
                                       params.adaptive ? 1 : 0,
                                       params.pixels_per_texel};
    device_->run(pass,
                 {{{PN_BLUR_SOURCE_BINDING, in},
                   {PN_BLUR_DEPTH_BINDING, depth != nullptr ? *depth : source},
                   {PN_BLUR_FILTER_MAP_BINDING, params.adaptive ? *filter_map : source}},
                  {{PN_BLUR_TARGET_BINDING, out}},
                  {},
                  query_block(block)},
                 width, height);
  };
  one_pass(source, *temporary, 1, 0);
  one_pass(*temporary, *target, 0, 1);
  return target;
}

}  // namespace pn
