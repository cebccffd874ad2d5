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

namespace {

// The program of one variant (blur.comp's PN_BLUR_PASS_* switches); index depth_aware * 2 + adaptive.
int variant(bool depth_aware, bool adaptive) { return (depth_aware ? 2 : 0) + (adaptive ? 1 : 0); }

}  // namespace

BlurPass::BlurPass(const Context& context, const SourceTree& tree) : context_(&context) {
  const auto truth = [](bool b) { return std::string(b ? "true" : "false"); };
  for (int v = 0; v < 4; ++v)  // limits: glsl/blur.h, as the reference
    programs_.push_back(compile_pass(context, tree, "passes/blur.comp",
                                     {{"PN_BLUR_PASS_DEPTH_AWARE", truth(v & 2)}, {"PN_BLUR_PASS_ADAPTIVE", truth(v & 1)}}));
}

GlObject BlurPass::run(const GlObject& source, const GlObject* depth, int width, int height,
                       const BlurParams& params, const GlObject* filter_map) const {
  params.validate();
  if (params.adaptive && filter_map == nullptr)
    throw Error("blur: the adaptive radius needs the filter-region map (none given)");
  GlObject temporary = make_float_texture(*context_, width, height, 1);
  GlObject target = make_float_texture(*context_, width, height, 1);

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
    bind.image(PN_BLUR_TARGET_BINDING, out, GL_WRITE_ONLY, GL_R32F);
    programs_[static_cast<size_t>(variant(params.depth_aware, params.adaptive))].dispatch(width, height);
  };
  one_pass(source, temporary, 1, 0);
  one_pass(temporary, target, 0, 1);
  return target;
}

}  // namespace pn
