#include "passes/region_pass.h"

#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"

namespace pn::glsl {
#include "passes/region_query.h"
PN_STD140_SIZE(PnRegionQueryParams, 16);
PN_STD140_OFFSET(PnRegionQueryParams, centred, 4);
}  // namespace pn::glsl

namespace pn {

RegionQuery::RegionQuery(const Context& context, const SourceTree& tree)
    : context_(&context), program_(compile_pass(context, tree, "passes/region_query.comp")) {}

Image RegionQuery::run(const Image& queries, int map_size, bool centred) const {
  if (map_size < 1) throw Error("region map size " + std::to_string(map_size) + ": expected N >= 1");
  const GlObject query_texture = upload_float_texture(*context_, queries);
  const GlObject results = make_float_texture(*context_, queries.width, queries.height, 4);
  {
    const glsl::PnRegionQueryParams block{map_size, centred ? 1 : 0};
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_REGION_QUERY_QUERIES_BINDING, query_texture);
    bind.image(PN_REGION_QUERY_RESULTS_BINDING, results, GL_WRITE_ONLY, GL_RGBA32F);
    program_.dispatch(queries.width, queries.height);
  }
  return read_float_texture(*context_, results, queries.width, queries.height, 4);
}

}  // namespace pn
