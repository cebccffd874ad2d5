#include "passes/pcss_regions_pass.h"

#include <string>

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/pass_bindings.h"
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
                  static_cast<int>(PcssRegionsQuery::Kind::search_mip) == PN_PCSS_REGIONS_QUERY_SEARCH_MIP,
              "query kinds as pcss_regions_query.h numbers them");

PcssRegionsQueryPass::PcssRegionsQueryPass(const Context& context, const SourceTree& tree)
    : context_(&context),
      program_(compile_pass(context, tree, "passes/pcss_regions_query.comp")),
      no_mip_(make_placeholder_texture(context, GL_TEXTURE_2D, GL_RGBA32F)) {}

std::vector<PcssRegionsResult> PcssRegionsQueryPass::run(const DepthPyramid& pyramid, const LightModel& light,
                                                         const std::vector<PcssRegionsQuery>& queries,
                                                         const MinMaxMipChain* mip) const {
  if (queries.empty()) return {};
  if (mip && mip->map_size != light.map_size)
    throw Error("pcss_regions query: light map size " + std::to_string(light.map_size) + ": expected the mip chain's " +
                std::to_string(mip->map_size));
  for (const PcssRegionsQuery& q : queries)
    if (q.kind == PcssRegionsQuery::Kind::search_mip && !mip)
      throw Error("pcss_regions query: a search over the mip chain needs the chain");
  if (light.map_size != pyramid.map_size)
    throw Error("pcss_regions query: light map size " + std::to_string(light.map_size) + ": expected the pyramid's " +
                std::to_string(pyramid.map_size));
  std::vector<Query> a, b, c;
  for (const PcssRegionsQuery& q : queries) {
    a.push_back({q.input[0], q.input[1], q.input[2], q.input[3]});
    b.push_back({float(static_cast<int>(q.kind)), float(static_cast<int>(q.mode)), float(q.iterations),
                 q.has_blocker ? 1.0f : 0.0f});
    c.push_back({q.bias, q.blocker_mean, q.filter_scale, 0.0f});
  }
  const Image image_a = query_image(a), image_b = query_image(b), image_c = query_image(c);
  const int w = image_a.width, h = image_a.height;
  const GlObject texture_a = upload_float_texture(*context_, image_a);
  const GlObject texture_b = upload_float_texture(*context_, image_b);
  const GlObject texture_c = upload_float_texture(*context_, image_c);
  const GlObject entries = make_float_texture(*context_, w, h, 4), rects = make_float_texture(*context_, w, h, 4);
  const GlObject windows = make_float_texture(*context_, w, h, 4), keys = make_float_texture(*context_, w, h, 4);
  {
    glsl::PnPcssRegionsQueryParams block{};
    set_light_fields(block, light);
    PassBindings bind(*context_);
    bind.uniform(block);
    bind.texture(PN_PCSS_REGIONS_QUERY_PYRAMID_BINDING, pyramid.texture);
    bind.texture(PN_PCSS_REGIONS_QUERY_MIP_BINDING, mip ? mip->texture : no_mip_);
    bind.texture(PN_PCSS_REGIONS_QUERY_A_BINDING, texture_a);
    bind.texture(PN_PCSS_REGIONS_QUERY_B_BINDING, texture_b);
    bind.texture(PN_PCSS_REGIONS_QUERY_C_BINDING, texture_c);
    bind.image(PN_PCSS_REGIONS_QUERY_ENTRY_BINDING, entries, GL_WRITE_ONLY, GL_RGBA32F);
    bind.image(PN_PCSS_REGIONS_QUERY_RECT_BINDING, rects, GL_WRITE_ONLY, GL_RGBA32F);
    bind.image(PN_PCSS_REGIONS_QUERY_WINDOW_BINDING, windows, GL_WRITE_ONLY, GL_RGBA32F);
    bind.image(PN_PCSS_REGIONS_QUERY_KEY_BINDING, keys, GL_WRITE_ONLY, GL_RGBA32F);
    program_.dispatch(w, h);
  }
  const Image e = read_float_texture(*context_, entries, w, h, 4), r = read_float_texture(*context_, rects, w, h, 4);
  const Image v = read_float_texture(*context_, windows, w, h, 4), k = read_float_texture(*context_, keys, w, h, 4);
  std::vector<PcssRegionsResult> out(queries.size());
  for (size_t i = 0; i < queries.size(); ++i) {
    const int x = static_cast<int>(i) % w, y = static_cast<int>(i) / w;
    for (int ch = 0; ch < 4; ++ch) {
      out[i].entry[ch] = e.at(x, y, ch), out[i].rect[ch] = r.at(x, y, ch);
      out[i].window[ch] = v.at(x, y, ch), out[i].key[ch] = k.at(x, y, ch);
    }
  }
  return out;
}

}  // namespace pn
