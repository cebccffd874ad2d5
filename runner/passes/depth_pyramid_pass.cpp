#include "passes/depth_pyramid_pass.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "gl/texture.h"
#include "reference/pyramid_reference.h"

namespace pn {

std::size_t DepthPyramid::memory_bytes(int map_size, int levels) {
  return std::size_t{16} * static_cast<std::size_t>(map_size) * map_size * levels;
}

void validate_shadow_map_size(int width, int height) {
  if (width != height)
    throw Error("shadow map " + std::to_string(width) + "x" + std::to_string(height) +
                ": expected a square map (N x N)");
  if (width < 2)
    throw Error("shadow map " + std::to_string(width) + "x" + std::to_string(height) + ": expected N >= 2");
}

DepthPyramidBuilder::DepthPyramidBuilder(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/depth_pyramid_build.comp")) {}

DepthPyramid DepthPyramidBuilder::build(const GlObject& shadow_map, int width, int height, int max_level) const {
  validate_shadow_map_size(width, height);
  DepthPyramid pyramid;
  pyramid.map_size = width;
  pyramid.levels = pyramid_level_count(width, max_level);
  pyramid.texture = make_float_texture_array(*context_, width, width, pyramid.levels, 4);
  build_into(shadow_map, pyramid);
  return pyramid;
}

void DepthPyramidBuilder::build_into(const GlObject& shadow_map, const DepthPyramid& pyramid) const {
  const auto& gl = context_->gl();
  gl.BindTextureUnit(0, shadow_map.id());
  gl.BindTextureUnit(1, pyramid.texture.id());
  gl.BindImageTexture(2, pyramid.texture.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  for (int level = 0; level < pyramid.levels; ++level) {
    const std::int32_t block[4] = {level, 0, 0, 0};
    GlObject params = bind_uniform_buffer(*context_, 3, block, sizeof block);
    const int size = pyramid.map_size - (1 << level) + 1;
    program_.dispatch(size, size);  // ends with the barrier the next level's fetches need
  }
}

DepthPyramidQuery::DepthPyramidQuery(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/depth_pyramid_query.comp")) {}

Image DepthPyramidQuery::run(const DepthPyramid& pyramid, const Image& queries) const {
  const GlObject query_texture = upload_float_texture(*context_, queries);
  const GlObject results = make_float_texture(*context_, queries.width, queries.height, 4);
  const auto& gl = context_->gl();
  gl.BindTextureUnit(0, pyramid.texture.id());
  gl.BindTextureUnit(1, query_texture.id());
  gl.BindImageTexture(2, results.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  program_.dispatch(queries.width, queries.height);
  return read_float_texture(*context_, results, queries.width, queries.height, 4);
}

}  // namespace pn
