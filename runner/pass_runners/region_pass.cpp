#include "pass_runners/region_pass.h"

#include <string>

#include "core/error.h"
#include "gl/std140.h"

namespace pn::glsl {
#include "passes/region_query.h"
PN_STD140_SIZE(PnRegionQueryParams, 16);
PN_STD140_OFFSET(PnRegionQueryParams, centred, 4);
PN_STD140_OFFSET(PnRegionQueryParams, areas, 8);
}  // namespace pn::glsl

namespace pn {

RegionQuery::RegionQuery(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/region_query.comp",
             {{PN_REGION_QUERY_QUERIES_BINDING}, {PN_REGION_QUERY_RESULTS_BINDING}}) {}

Image RegionQuery::run(const Image& queries, int map_size, bool centred) const {
  if (map_size < 1) throw Error("region map size " + std::to_string(map_size) + ": expected N >= 1");
  const glsl::PnRegionQueryParams block{map_size, centred ? 1 : 0, 0};
  return query_.run(std::vector<Image>{queries}, {}, query_block(block)).images.front();
}

Image RegionQuery::run_areas(const Image& queries, int map_size) const {
  if (map_size < 1) throw Error("region map size " + std::to_string(map_size) + ": expected N >= 1");
  const glsl::PnRegionQueryParams block{map_size, 0, 1};
  return query_.run(std::vector<Image>{queries}, {}, query_block(block)).images.front();
}

}  // namespace pn
