#include "passes/depth_pyramid_pass.h"

#include "gl/query_device_gl.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "modules/depth_pyramid.h"

namespace pn::glsl {
#include "passes/depth_pyramid.h"
PN_STD140_SIZE(PnPyramidBuildParams, 16);
PN_STD140_OFFSET(PnPyramidBuildParams, level, 0);
PN_STD140_OFFSET(PnPyramidBuildParams, texelCount, 8);
}  // namespace pn::glsl

namespace pn {

std::size_t DepthPyramid::memory_bytes(int map_size, int levels) {
  return std::size_t{16} * static_cast<std::size_t>(map_size) * map_size * levels;
}

Image read_pyramid_level(const Context& context, const DepthPyramid& pyramid, int level) {
  const int size = pyramid.level_size(level);
  return read_float_texture_layer(context, pyramid.texture, level, size, size, 4);
}

void validate_shadow_map_size(int width, int height) {
  if (width != height)
    throw Error("shadow map " + std::to_string(width) + "x" + std::to_string(height) +
                ": expected a square map (N x N)");
  if (width < 2)
    throw Error("shadow map " + std::to_string(width) + "x" + std::to_string(height) + ": expected N >= 2");
}

DepthPyramidBuilder::DepthPyramidBuilder(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/depth_pyramid_build.comp")),
      no_texels_(make_buffer(context, 2 * sizeof(int), nullptr)) {}

DepthPyramid DepthPyramidBuilder::build(const GlObject& shadow_map, int width, int height, int max_level) const {
  validate_shadow_map_size(width, height);
  DepthPyramid pyramid;
  pyramid.map_size = width;
  pyramid.levels = pyramid_level_count(width, max_level);
  pyramid.texture = make_float_texture_array(*context_, width, width, pyramid.levels, 4);
  build_into(shadow_map, pyramid);
  // A view of the immutable storage (or, on an ES context without views, a copy of the built layer).
  pyramid.level0 = texture_of_layer(*context_, pyramid.texture, 0, width, width, 4);
  return pyramid;
}

void DepthPyramidBuilder::dispatch_level(const GlObject& shadow_map, const DepthPyramid& pyramid, int level,
                                         TexelRun run, const GlObject& texels) const {
  if (!run.whole && run.count <= 0) return;
  const bool listed = run.count > 0 && !run.whole;
  PassBindings bind(*context_);
  bind.texture(PN_PYRAMID_BUILD_MAP_BINDING, shadow_map);
  bind.texture(PN_PYRAMID_BUILD_READ_BINDING, pyramid.texture);
  bind.image(PN_PYRAMID_BUILD_WRITE_IMAGE, pyramid.texture, GL_WRITE_ONLY, GL_RGBA32F, 0, true);
  bind.storage_buffer(PN_PYRAMID_BUILD_TEXELS_BINDING, listed ? texels : no_texels_);
  bind.uniform(glsl::PnPyramidBuildParams{level, run.first, listed ? run.count : 0});
  const int size = pyramid.level_size(level);
  // Ends with the barrier the next level's fetches need.
  dispatch_texel_run(program_, run, size, size);
}

void DepthPyramidBuilder::build_into(const GlObject& shadow_map, const DepthPyramid& pyramid) const {
  for (int level = 0; level < pyramid.levels; ++level) dispatch_level(shadow_map, pyramid, level, {0, 0, true}, no_texels_);
}

void DepthPyramidBuilder::update_into(const GlObject& shadow_map, DepthPyramid& pyramid,
                                      const std::vector<TexelRect>& rects, TexelList& texels, bool dilate) const {
  texels.clear();
  std::vector<TexelRun> runs;
  std::vector<TexelRect> at_level;
  for (int level = 0; level < pyramid.levels; ++level) {
    const int size = pyramid.level_size(level), reach = dilate ? (1 << level) - 1 : 0;
    at_level.clear();
    for (const TexelRect& r : rects)
      if (!r.empty()) at_level.push_back({r.x0 - reach, r.y0 - reach, r.x1, r.y1});
    runs.push_back(texels.add(at_level, size, size));
  }
  texels.upload(*context_);
  for (int level = 0; level < pyramid.levels; ++level)
    dispatch_level(shadow_map, pyramid, level, runs[static_cast<size_t>(level)], texels.buffer());
  pyramid.level0 = texture_of_layer(*context_, pyramid.texture, 0, pyramid.map_size, pyramid.map_size, 4);
}

DepthPyramidQuery::DepthPyramidQuery(const Context& context, const SourceTree& tree)
    : query_(context, tree, "passes/depth_pyramid_query.comp",
             {{PN_PYRAMID_QUERY_QUERIES_BINDING}, {PN_PYRAMID_QUERY_RESULTS_IMAGE}}) {}

Image DepthPyramidQuery::run(const DepthPyramid& pyramid, const Image& queries) const {
  return query_.run(std::vector<Image>{queries}, {{PN_PYRAMID_QUERY_PYRAMID_BINDING, GlDeviceTexture(pyramid.texture)}}).images.front();
}

}  // namespace pn
