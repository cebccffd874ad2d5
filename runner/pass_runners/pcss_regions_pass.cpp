#include "pass_runners/pcss_regions_pass.h"

#include "gl/query_device_gl.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/pcss_regions_query.h"
PN_STD140_SIZE(PnPcssRegionsQueryParams, 32);
PN_STD140_OFFSET(PnPcssRegionsQueryParams, lightNear, 4);
PN_STD140_OFFSET(PnPcssRegionsQueryParams, mapSize, 12);
}  // namespace pn::glsl

namespace pn {

static_assert(static_cast<int>(PcssRegionsQuery::Kind::search) == PN_PCSS_REGIONS_QUERY_SEARCH &&
                  static_cast<int>(PcssRegionsQuery::Kind::filter) == PN_PCSS_REGIONS_QUERY_FILTER &&
                  static_cast<int>(PcssRegionsQuery::Kind::entry) == PN_PCSS_REGIONS_QUERY_ENTRY &&
                  static_cast<int>(PcssRegionsQuery::Kind::search_mip) == PN_PCSS_REGIONS_QUERY_SEARCH_MIP &&
                  static_cast<int>(PcssRegionsQuery::Kind::search_mip_counted) == PN_PCSS_REGIONS_QUERY_SEARCH_MIP_COUNTED &&
                  static_cast<int>(PcssRegionsQuery::Kind::search_mip_plane) == PN_PCSS_REGIONS_QUERY_SEARCH_MIP_PLANE &&
                  static_cast<int>(PcssRegionsQuery::Kind::search_plane) == PN_PCSS_REGIONS_QUERY_SEARCH_PLANE,
              "query kinds as pcss_regions_query.h numbers them");

PcssRegionsQueryPass::PcssRegionsQueryPass(const QueryDevice& device, const SourceTree& tree, bool area_edges)
    : query_(device, tree, "passes/pcss_regions_query.comp",
             {{PN_PCSS_REGIONS_QUERY_A_BINDING, PN_PCSS_REGIONS_QUERY_B_BINDING, PN_PCSS_REGIONS_QUERY_C_BINDING},
              {PN_PCSS_REGIONS_QUERY_ENTRY_BINDING, PN_PCSS_REGIONS_QUERY_RECT_BINDING,
               PN_PCSS_REGIONS_QUERY_WINDOW_BINDING, PN_PCSS_REGIONS_QUERY_KEY_BINDING}},
             {{"PN_AREA_EDGES", area_edges ? "1" : "0"}}),
      no_mip_(device.make_texture({TexelFormat::rgba32f, 1, 1})) {}

std::vector<PcssRegionsResult> PcssRegionsQueryPass::run(const DepthPyramid& pyramid, const LightModel& light,
                                                         const std::vector<PcssRegionsQuery>& queries,
                                                         const MinMaxMipChain* mip) const {
  if (queries.empty()) return {};
  if (mip && mip->map_size != light.map_size)
    throw Error("pcss_regions query: light map size " + std::to_string(light.map_size) + ": expected the mip chain's " +
                std::to_string(mip->map_size));
  for (const PcssRegionsQuery& q : queries)
    if ((q.kind == PcssRegionsQuery::Kind::search_mip || q.kind == PcssRegionsQuery::Kind::search_mip_counted ||
         q.kind == PcssRegionsQuery::Kind::search_mip_plane) &&
        !mip)
      throw Error("pcss_regions query: a search over the mip chain needs the chain");
  if (light.map_size != pyramid.map_size)
    throw Error("pcss_regions query: light map size " + std::to_string(light.map_size) + ": expected the pyramid's " +
                std::to_string(pyramid.map_size));
  std::vector<Query> a, b, c;
  for (const PcssRegionsQuery& q : queries) {
    a.push_back({q.input[0], q.input[1], q.input[2], q.input[3]});
    b.push_back({float(static_cast<int>(q.kind)), float(static_cast<int>(q.mode)), float(q.iterations),
                 q.has_blocker ? 1.0f : 0.0f});
    const bool plane =
        q.kind == PcssRegionsQuery::Kind::search_mip_plane || q.kind == PcssRegionsQuery::Kind::search_plane;  // its gradient where a filter's inputs go
    c.push_back({q.bias, plane ? q.gradient[0] : q.blocker_mean, plane ? q.gradient[1] : q.filter_scale, 0.0f});
  }
  glsl::PnPcssRegionsQueryParams block{};
  set_light_fields(block, light);
  const QueryResults r = query_.run({a, b, c},
                                    {{PN_PCSS_REGIONS_QUERY_PYRAMID_BINDING, *pyramid.texture},
                                     {PN_PCSS_REGIONS_QUERY_MIP_BINDING, mip ? *mip->texture : *no_mip_}},
                                    query_block(block));
  std::vector<PcssRegionsResult> out(queries.size());
  for (size_t i = 0; i < queries.size(); ++i) {
    out[i] = {r.at(0, i), r.at(1, i), r.at(2, i), r.at(3, i)};
    const float packed = out[i].window[3];  // pnEntryLit + 2 × refinements
    out[i].refinements = static_cast<int>(std::floor(packed / 2.0f));
    out[i].window[3] = packed - 2.0f * static_cast<float>(out[i].refinements);
  }
  return out;
}

}  // namespace pn
