#include "passes/region_pass.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "gl/texture.h"

namespace pn {

RegionQuery::RegionQuery(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/region_query.comp")) {}

Image RegionQuery::run(const Image& queries, int map_size, bool centred) const {
  if (map_size < 1) throw Error("region map size " + std::to_string(map_size) + ": expected N >= 1");
  const GlObject query_texture = upload_float_texture(*context_, queries);
  const GlObject results = make_float_texture(*context_, queries.width, queries.height, 4);
  const std::int32_t block[4] = {map_size, centred ? 1 : 0, 0, 0};
  GlObject params = bind_uniform_buffer(*context_, 3, block, sizeof block);
  const auto& gl = context_->gl();
  gl.BindTextureUnit(0, query_texture.id());
  gl.BindImageTexture(2, results.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  program_.dispatch(queries.width, queries.height);
  return read_float_texture(*context_, results, queries.width, queries.height, 4);
}

}  // namespace pn
