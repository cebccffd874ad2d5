#include "pass_runners/pcf_pass.h"

#include "core/error.h"

#include <string>

#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "passes/pcf_query.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/pcf_shade.h"
PN_STD140_SIZE(PnPcfShadeParams, 32);
}  // namespace pn::glsl

namespace pn {
namespace {

// The first `count` results as sums: (occluders, depth sum, texels, ratio) a query.
std::vector<PcfQueryResult> sums(const QueryResults& r, std::size_t count) {
  std::vector<PcfQueryResult> out;
  for (std::size_t k = 0; k < count; ++k) {
    const Query q = r.at(0, k);
    out.push_back({q[0], q[1], q[2], q[3]});
  }
  return out;
}

std::vector<Define> max_side_define(int max_side) {
  if (max_side <= 0) return {};
  return {{"PN_PCF_MAX_SIDE", std::to_string(max_side)}};
}

}  // namespace

PcfQueryPass::PcfQueryPass(const QueryDevice& device, const SourceTree& tree, int max_side)
    : query_(device, tree, "passes/pcf_query.comp",
             {{PN_PCF_QUERY_A_BINDING, PN_PCF_QUERY_B_BINDING, PN_PCF_QUERY_C_BINDING}, {PN_PCF_QUERY_RESULT_IMAGE}},
             max_side_define(max_side)) {}

QueryResults PcfQueryPass::dispatch(const DeviceTexture& depth_map, const std::vector<Query>& a,
                                    const std::vector<Query>& b, std::vector<Query> c) const {
  if (c.empty()) c.assign(a.size(), Query{0.0f, 0.0f, 0.0f, 0.0f});
  return query_.run({a, b, c}, {{PN_PCF_QUERY_MAP_BINDING, depth_map}});
}

std::vector<PcfQueryResult> PcfQueryPass::run(const DeviceTexture& depth_map, const std::vector<PcfQuery>& queries,
                                              const std::vector<PcfPlane>& planes) const {
  if (queries.empty()) return {};
  if (planes.size() != queries.size()) throw Error("pcf query: a plane per query expected");
  std::vector<Query> a, b, c;
  for (size_t k = 0; k < queries.size(); ++k) {
    const PcfQuery& q = queries[k];
    const PcfPlane& p = planes[k];
    a.push_back({float(q.x), float(q.y), float(q.width), float(q.height)});
    b.push_back({q.receiver_depth, q.bias, float(q.band_rows), 3.0f});
    c.push_back({p.gradient_u, p.gradient_v, p.centre_u, p.centre_v});
  }
  return sums(dispatch(depth_map, a, b, c), queries.size());
}

std::vector<PcfQueryResult> PcfQueryPass::area(const DeviceTexture& depth_map, const std::vector<PcfAreaQuery>& queries,
                                               const std::vector<PcfPlane>& planes) const {
  if (queries.empty()) return {};
  if (planes.size() != queries.size()) throw Error("pcf query: a plane per query expected");
  std::vector<Query> a, b, c;
  for (size_t k = 0; k < queries.size(); ++k) {
    const PcfAreaQuery& q = queries[k];
    a.push_back({q.x, q.y, q.side, 0.0f});
    b.push_back({q.receiver_depth, q.bias, float(q.band_rows), 4.0f});
    c.push_back({planes[k].gradient_u, planes[k].gradient_v, 0.0f, 0.0f});
  }
  return sums(dispatch(depth_map, a, b, c), queries.size());
}

std::vector<PcfQueryResult> PcfQueryPass::run(const DeviceTexture& depth_map, const std::vector<PcfQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> a, b;
  for (const PcfQuery& q : queries) {
    a.push_back({float(q.x), float(q.y), float(q.width), float(q.height)});
    b.push_back({q.receiver_depth, q.bias, float(q.band_rows), 0.0f});
  }
  return sums(dispatch(depth_map, a, b), queries.size());
}

std::vector<PcfQueryResult> PcfQueryPass::area(const DeviceTexture& depth_map,
                                               const std::vector<PcfAreaQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> a, b;
  for (const PcfAreaQuery& q : queries) {
    a.push_back({q.x, q.y, q.side, 0.0f});
    b.push_back({q.receiver_depth, q.bias, float(q.band_rows), 2.0f});
  }
  return sums(dispatch(depth_map, a, b), queries.size());
}

std::vector<float> PcfQueryPass::bilinear(const DeviceTexture& depth_map, const std::vector<PcfBilinearQuery>& queries) const {
  if (queries.empty()) return {};
  std::vector<Query> a, b;
  for (const PcfBilinearQuery& q : queries) {
    a.push_back({q.x, q.y, q.gradient_u, q.gradient_v});
    b.push_back({q.receiver_depth, q.bias, 0.0f, 1.0f});
  }
  const QueryResults r = dispatch(depth_map, a, b);
  std::vector<float> out;
  for (size_t k = 0; k < queries.size(); ++k) out.push_back(r.at(0, k)[0]);
  return out;
}

PcfShadePass::PcfShadePass(const QueryDevice& device, const SourceTree& tree)
    : shade_(device, tree, "passes/pcf_shade", PN_PCF_SHADE_VISIBILITY_IMAGE) {}

std::unique_ptr<DeviceTexture> PcfShadePass::run(const DeviceTexture& shadow_map, const DeviceTexture& gbuffer,
                                                 int screen_size, const LightModel& light, float bias,
                                                 float receiver_plane_tan, ShadeStage stage) const {
  glsl::PnPcfShadeParams block{};
  set_light_fields(block, light);
  block.bias = bias;
  block.receiverPlaneTan = receiver_plane_tan;
  PassResources resources;
  resources.block = query_block(block);
  resources.add_textures({{PN_PCF_SHADE_MAP_BINDING, shadow_map}, {PN_PCF_SHADE_GBUFFER_BINDING, gbuffer}});
  return shade_.run(stage, {}, screen_size, resources);
}

}  // namespace pn
