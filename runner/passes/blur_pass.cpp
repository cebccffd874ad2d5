#include "passes/blur_pass.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/blur.h"
PN_STD140_SIZE(PnBlurPassParams, 32);
PN_STD140_OFFSET(PnBlurPassParams, radius, 8);
PN_STD140_OFFSET(PnBlurPassParams, depthTolerance, 20);
PN_STD140_OFFSET(PnBlurPassParams, pixelsPerTexel, 28);
}  // namespace pn::glsl

namespace pn {

BlurPass::BlurPass(const Context& context, const SourceTree& tree)
    : context_(&context), variants_(context, tree, "passes/blur.comp") {
  for (int v = 0; v < 4; ++v) {  // the single-channel variants now, so a copy that does not compile fails here
    BlurParams params;
    params.depth_aware = (v & 2) != 0;
    params.adaptive = (v & 1) != 0;
    program(params, 1);
  }
}

const ComputeProgram& BlurPass::program(const BlurParams& params, int channels) const {
  const auto truth = [](bool b) { return std::string(b ? "true" : "false"); };
  return variants_.get({{"PN_BLUR_PASS_DEPTH_AWARE", truth(params.depth_aware)},
                        {"PN_BLUR_PASS_ADAPTIVE", truth(params.adaptive)},
                        {"PN_BLUR_PASS_CHANNELS", std::to_string(channels)}});
}

FloatTexture BlurPass::run(const GlObject& source, const GlObject* depth, int width, int height,
                           const BlurParams& params, const GlObject* filter_map, int channels) const {
  params.validate();
  if (channels != 1 && channels != 2 && channels != 4)
    throw Error("blur: " + std::to_string(channels) + " channels: expected 1, 2 or 4");
  if (params.adaptive && filter_map == nullptr)
    throw Error("blur: the adaptive radius needs the filter-region map (none given)");
  const ComputeProgram& pass = program(params, channels);
  const int stored = image_channels(*context_, channels);
  GlObject temporary = make_float_texture(*context_, width, height, stored);
  FloatTexture target = make_float_texture(*context_, width, height, stored);

  auto one_pass = [&](const GlObject& in, const GlObject& out, int ax, int ay) {
    const glsl::PnBlurPassParams block{{ax, ay},
                                       params.radius,
                                       static_cast<float>(params.sigma),
                                       params.depth_aware ? 1 : 0,
                                       static_cast<float>(params.depth_tolerance),
                                       params.adaptive ? 1 : 0,
                                       params.pixels_per_texel};
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_BLUR_SOURCE_BINDING, in);
    bind.texture(PN_BLUR_DEPTH_BINDING, depth != nullptr ? *depth : source);
    bind.texture(PN_BLUR_FILTER_MAP_BINDING, params.adaptive ? *filter_map : source);
    bind.image(PN_BLUR_TARGET_BINDING, out, GL_WRITE_ONLY, float_format(stored));
    pass.dispatch(width, height);
  };
  one_pass(source, temporary, 1, 0);
  one_pass(temporary, target, 0, 1);
  return target;
}

}  // namespace pn
