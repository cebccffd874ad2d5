#include "pass_runners/vsm_pass.h"

#include "gl/query_device_gl.h"

#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/vsm_moments.h"
#include "passes/vsm_query.h"
#include "passes/vsm_shade.h"
PN_STD140_SIZE(PnVsmMomentsParams, 16);
PN_STD140_OFFSET(PnVsmMomentsParams, exponents, 8);
PN_STD140_SIZE(PnVsmQueryParams, 32);
PN_STD140_OFFSET(PnVsmQueryParams, kind, 16);
PN_STD140_OFFSET(PnVsmQueryParams, radius, 20);
PN_STD140_OFFSET(PnVsmQueryParams, minVariance, 24);
PN_STD140_OFFSET(PnVsmQueryParams, bleedingReduction, 28);
PN_STD140_SIZE(PnVsmShadeParams, 32);
PN_STD140_OFFSET(PnVsmShadeParams, radius, 16);
PN_STD140_OFFSET(PnVsmShadeParams, bias, 20);
PN_STD140_OFFSET(PnVsmShadeParams, bleedingReduction, 28);
}  // namespace pn::glsl

namespace pn {

VsmMomentsPass::VsmMomentsPass(const QueryDevice& device, const SourceTree& tree)
    : device_(&device), tree_(&tree), blur_(device, tree) {}

VsmMoments VsmMomentsPass::moments(const DeviceTexture& depth_map, int width, int height,
                                   const VsmParams& params) const {
  params.validate();
  validate_shadow_map_size(width, height);
  const int kind = static_cast<int>(params.kind);
  std::unique_ptr<QueryProgram>& program = variants_[kind];
  if (!program)
    program = device_->compile_query(*tree_, "passes/vsm_moments.comp", {{"PN_VSM_MOMENTS_KIND", std::to_string(kind)}});
  const int channels = vsm_moment_channels(params.kind);
  // The shader writes rgba32f for EVSM-4 and, on ES, for every kind (no rg32f image format there).
  const int stored = device_->storage_channels(channels);
  VsmMoments out{device_->make_texture(float_shape(width, height, stored)), width, channels, stored};
  const glsl::PnVsmMomentsParams block{{params.near_depth, params.far_depth},
                                       {params.positive_exponent, params.negative_exponent}};
  device_->run(*program,
               {{{PN_VSM_MOMENTS_MAP_BINDING, depth_map}}, {{PN_VSM_MOMENTS_TARGET_BINDING, *out.texture}}, {},
                query_block(block)},
               width, height);
  return out;
}

VsmMoments VsmMomentsPass::blurred(const VsmMoments& moments, const VsmParams& params) const {
  return {blur_.run(*moments.texture, nullptr, moments.size, moments.size, params.blur, nullptr, moments.channels),
          moments.size, moments.channels, device_->storage_channels(moments.channels)};
}

VsmQueryPass::VsmQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/vsm_query.comp", {{PN_VSM_QUERY_QUERIES_BINDING}, {PN_VSM_QUERY_RESULTS_IMAGE}}) {}

std::vector<Query> VsmQueryPass::run(const VsmMoments& moments, const DepthPyramid& pyramid,
                                     const std::vector<VsmQuery>& queries, const VsmParams& params) const {
  params.validate();
  if (queries.empty()) return {};
  std::vector<Query> q;
  for (const VsmQuery& v : queries) q.push_back({float(v.x), float(v.y), v.receiver_depth, v.bias});
  const glsl::PnVsmQueryParams block{{params.near_depth, params.far_depth},
                                     {params.positive_exponent, params.negative_exponent},
                                     static_cast<int>(params.kind),
                                     params.blur.radius,
                                     params.min_variance,
                                     params.bleeding_reduction};
  return query_
      .run({q}, {{PN_VSM_QUERY_MOMENTS_BINDING, *moments.texture},
                 {PN_VSM_QUERY_PYRAMID_BINDING, *pyramid.texture}},
           query_block(block))
      .list(0, queries.size());
}

VsmShadePass::VsmShadePass(const QueryDevice& device, const SourceTree& tree)
    : shade_(device, tree, "passes/vsm_shade", PN_VSM_SHADE_VISIBILITY_IMAGE) {}

std::unique_ptr<DeviceTexture> VsmShadePass::run(const VsmMoments& moments, const DepthPyramid& pyramid,
                                                 const DeviceTexture& gbuffer, int screen_size,
                                                 const VsmParams& params, float bias, ShadeStage stage) const {
  params.validate();
  const glsl::PnVsmShadeParams block{{params.near_depth, params.far_depth},
                                     {params.positive_exponent, params.negative_exponent},
                                     params.blur.radius,
                                     bias,
                                     params.min_variance,
                                     params.bleeding_reduction};
  PassResources resources;
  resources.block = query_block(block);
  resources.add_textures({{PN_VSM_SHADE_MOMENTS_BINDING, *moments.texture},
                          {PN_VSM_SHADE_PYRAMID_BINDING, *pyramid.texture},
                          {PN_VSM_SHADE_GBUFFER_BINDING, gbuffer}});
  return shade_.run(stage, {{"PN_VSM_SHADE_KIND", std::to_string(static_cast<int>(params.kind))}}, screen_size,
                    resources);
}

}  // namespace pn
