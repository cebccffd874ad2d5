#include "pass_runners/savsm_pass.h"

#include "gl/query_device_gl.h"

#include <string>

#include "core/error.h"
#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/savsm_params.h"
PN_STD140_SIZE(PnSavsmParams, 64);
PN_STD140_OFFSET(PnSavsmParams, unitRange, 24);
PN_STD140_OFFSET(PnSavsmParams, bias, 32);
PN_STD140_OFFSET(PnSavsmParams, blockerMode, 48);
PN_STD140_OFFSET(PnSavsmParams, bound, 52);
}  // namespace pn::glsl

namespace pn {
namespace {

glsl::PnSavsmParams make_block(const MomentsTable& table, const LightModel& light, const SavsmSettings& s) {
  s.validate();
  glsl::PnSavsmParams b{};
  set_light_fields(b, light);
  b.unitRange = {table.range.offset, table.range.scale};
  b.bias = s.bias;
  b.filterScale = s.filter_scale;
  b.minVariance = s.min_variance;
  b.bleedingReduction = s.bleeding_reduction;
  b.blockerMode = static_cast<int>(s.blocker);
  b.bound = s.bound ? 1 : 0;
  return b;
}

std::vector<Define> table_define(int kind) { return {{"PN_SAVSM_TABLE", std::to_string(kind)}}; }

std::vector<Define> table_define(const MomentsTable& table) {
  return table_define(table.kind == MomentsTableKind::fixed ? PN_SAVSM_TABLE_FIXED : PN_SAVSM_TABLE_FLOAT);
}

QueryBindings query_bindings() {
  return {{PN_SAVSM_INPUT_BINDING},
          {PN_SAVSM_SEARCH_IMAGE, PN_SAVSM_FILTER_IMAGE, PN_SAVSM_BLOCKER_IMAGE, PN_SAVSM_RESULT_IMAGE}};
}

void check_sizes(const MomentsTable& table, const LightModel& light) {
  if (table.width != table.height || table.width != light.map_size)
    throw Error("savsm: a moments table of a " + std::to_string(table.width) + "x" + std::to_string(table.height) +
                " map for a light of map size " + std::to_string(light.map_size) + ": expected the light's N×N map");
}

// Whether the settings are the module's defaults but the bias (pnSavsmDefaults): the shade pass then
// compiles them as constants, the program an engine's shader makes (docs/benchmarks.md).
bool engine_form(const SavsmSettings& s) {
  const SavsmSettings d;
  return s.filter_scale == d.filter_scale && s.min_variance == d.min_variance &&
         s.bleeding_reduction == d.bleeding_reduction && s.blocker == d.blocker && s.bound == d.bound;
}

Rect rect_of(const Query& q) {
  return {static_cast<int>(q[0]), static_cast<int>(q[1]), static_cast<int>(q[2]), static_cast<int>(q[3])};
}

}  // namespace

SavsmPass::SavsmPass(const QueryDevice& device, const SourceTree& tree)
    : shade_(device, tree, "passes/savsm_shade", PN_SAVSM_VISIBILITY_IMAGE) {}

SavsmQueryPass::SavsmQueryPass(const QueryDevice& device, const SourceTree& tree)
    : fixed_query_(device, tree, "passes/savsm_query.comp", query_bindings(), table_define(PN_SAVSM_TABLE_FIXED),
                   QueryCompile::on_first_use),
      float_query_(device, tree, "passes/savsm_query.comp", query_bindings(), table_define(PN_SAVSM_TABLE_FLOAT),
                   QueryCompile::on_first_use) {}

std::unique_ptr<DeviceTexture> SavsmPass::shade(const MomentsTable& table, const DeviceTexture& mip,
                                                const DeviceTexture& gbuffer, int screen_size, const LightModel& light,
                                                const SavsmSettings& settings, ShadeStage stage) const {
  check_sizes(table, light);
  const glsl::PnSavsmParams block = make_block(table, light, settings);
  PassResources resources;
  resources.block = query_block(block);
  resources.add_textures(
      {{PN_SAVSM_TABLE_BINDING, *table.texture}, {PN_SAVSM_MIP_BINDING, mip}, {PN_SAVSM_INPUT_BINDING, gbuffer}});
  std::vector<Define> defines = table_define(table);
  if (engine_form(settings)) defines.push_back({"PN_SAVSM_ENGINE_FORM", "1"});
  return shade_.run(stage, defines, screen_size, resources);
}

std::vector<SavsmQueryResult> SavsmQueryPass::query(const MomentsTable& table, const DeviceTexture& mip,
                                               const std::vector<SavsmReceiver>& receivers, const LightModel& light,
                                               const SavsmSettings& settings) const {
  check_sizes(table, light);
  if (receivers.empty()) return {};
  const glsl::PnSavsmParams block = make_block(table, light, settings);
  std::vector<Query> q;
  for (const SavsmReceiver& r : receivers) q.push_back({r.u, r.v, r.depth, 0.0f});
  const QueryPass& pass = table.kind == MomentsTableKind::fixed ? fixed_query_ : float_query_;
  const QueryResults r = pass.run(
      {q}, {{PN_SAVSM_TABLE_BINDING, *table.texture}, {PN_SAVSM_MIP_BINDING, mip}}, query_block(block));
  std::vector<SavsmQueryResult> out;
  for (size_t k = 0; k < receivers.size(); ++k) {
    SavsmQueryResult o;
    o.search = rect_of(r.at(0, k));
    o.filter = rect_of(r.at(1, k));
    const Query bk = r.at(2, k), rk = r.at(3, k);
    o.blocker = bk[0];
    o.has_blocker = bk[1] != 0.0f;
    o.filter_side = bk[2];
    o.fetches = bk[3];
    o.mean = rk[0];
    o.variance = rk[1];
    o.chebyshev = rk[2];
    o.visibility = rk[3];
    out.push_back(o);
  }
  return out;
}

}  // namespace pn
