#include "pass_runners/depth_pyramid_pass.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "gl/std140.h"
#include "modules/depth_pyramid_face.h"

namespace pn::glsl {
#include "passes/depth_pyramid_bindings.h"
PN_STD140_SIZE(PnPyramidBuildParams, 16);
PN_STD140_OFFSET(PnPyramidBuildParams, level, 0);
PN_STD140_OFFSET(PnPyramidBuildParams, texelCount, 8);
}  // namespace pn::glsl

namespace pn {

std::size_t DepthPyramid::memory_bytes(int map_size, int levels) {
  return std::size_t{16} * static_cast<std::size_t>(map_size) * map_size * levels;
}

Image read_pyramid_level(const QueryDevice& device, const DepthPyramid& pyramid, int level) {
  const int size = pyramid.level_size(level);
  return top_left(device.read_texture(*pyramid.texture, 0, level), size, size);
}

void validate_shadow_map_size(int width, int height) {
  if (width != height)
    throw Error("shadow map " + std::to_string(width) + "x" + std::to_string(height) +
                ": expected a square map (N x N)");
  if (width < 2)
    throw Error("shadow map " + std::to_string(width) + "x" + std::to_string(height) + ": expected N >= 2");
}

DepthPyramidBuilder::DepthPyramidBuilder(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_query(tree, "passes/depth_pyramid_build.comp", {})),
      no_texels_(device.make_buffer(2 * sizeof(int))) {}

DepthPyramid DepthPyramidBuilder::build(const DeviceTexture& shadow_map, int width, int height, int max_level) const {
  validate_shadow_map_size(width, height);
  DepthPyramid pyramid;
  pyramid.map_size = width;
  pyramid.levels = pyramid_level_count(width, max_level);
  pyramid.texture = device_->make_texture({TexelFormat::rgba32f, width, width, 1, pyramid.levels, true});
  build_into(shadow_map, pyramid);
  pyramid.level0 = device_->layer_texture(*pyramid.texture, 0);
  return pyramid;
}

void DepthPyramidBuilder::dispatch_level(const DeviceTexture& shadow_map, const DepthPyramid& pyramid, int level,
                                         TexelRun run, const DeviceBuffer& texels) const {
  if (!run.whole && run.count <= 0) return;
  const bool listed = run.count > 0 && !run.whole;
  const glsl::PnPyramidBuildParams block{level, run.first, listed ? run.count : 0};
  const int size = pyramid.level_size(level);
  const auto [width, height] = texel_run_grid(run, size, size);
  // Every layer bound as one image; the run makes the writes visible to the next level's fetches.
  device_->run(*program_,
               {{{PN_PYRAMID_BUILD_MAP_BINDING, shadow_map}, {PN_PYRAMID_BUILD_READ_BINDING, *pyramid.texture}},
                {{PN_PYRAMID_BUILD_WRITE_IMAGE, *pyramid.texture, 0}},
                {{PN_PYRAMID_BUILD_TEXELS_BINDING, listed ? texels : *no_texels_}},
                query_block(block)},
               width, height);
}

void DepthPyramidBuilder::build_into(const DeviceTexture& shadow_map, const DepthPyramid& pyramid) const {
  for (int level = 0; level < pyramid.levels; ++level) dispatch_level(shadow_map, pyramid, level, {0, 0, true}, *no_texels_);
}

void DepthPyramidBuilder::update_into(const DeviceTexture& shadow_map, DepthPyramid& pyramid,
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
  texels.upload(*device_);
  for (int level = 0; level < pyramid.levels; ++level)
    dispatch_level(shadow_map, pyramid, level, runs[static_cast<size_t>(level)], texels.buffer());
  pyramid.level0 = device_->layer_texture(*pyramid.texture, 0);
}

DepthPyramidQuery::DepthPyramidQuery(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/depth_pyramid_query.comp",
             {{PN_PYRAMID_QUERY_QUERIES_BINDING}, {PN_PYRAMID_QUERY_RESULTS_IMAGE}}) {}

Image DepthPyramidQuery::run(const DepthPyramid& pyramid, const Image& queries) const {
  return query_.run(std::vector<Image>{queries}, {{PN_PYRAMID_QUERY_PYRAMID_BINDING, *pyramid.texture}}).images.front();
}

}  // namespace pn
