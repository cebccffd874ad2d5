// Cases of the exports check (issue 27): the export entries — glsl/exports/X.comp, what
// `penumbra bundle X.glsl --target hlsl|msl` translates — run as query passes on the executor
// under check (on `--api hlsl`, the HLSL export itself, compiled back by glslang), against the
// CPU's definitions of the calls, for every pixel of each scene that sees a surface:
// - pnExactPcss against exact PCSS brute force (exact_pcss_reference, double);
// - pnPcf against 2×2 bilinear PCF (pcf_plane_reference, double);
// - pnHqepcss with its exact settings (no refinement, exact regions, leaf 1) over the decreased
//   depth pyramid built on the executor, against exact PCSS brute force;
// - pnFastPcss with its exact settings (no refinement, exact regions, leaf 1, the summed-area
//   table's blocker sums: exports/fast_pcss.comp with PN_EXPORT_SUM_TABLE) against exact PCSS
//   brute force, over the min/max mip chain and the table built on the same executor;
// each through both overloads (half the receivers through the receiverPlane one, with a zero
// plane, which must give the same), the pixels within rounding of a decision left out and
// counted. The shadow map and G-buffer are the CPU's ray casts (the shadow_map check holds the
// GPU's rasterised ones to them), so the check needs nothing but the executor.
#include <cmath>
#include <string>
#include <vector>

#include "check/module_check.h"
#include "check/pcss_compare.h"
#include "core/format.h"
#include "scenes.h"
#include "gl/std140.h"
#include "passes/depth_pyramid_pass.h"
#include "passes/export_pass.h"
#include "passes/minmax_mip_pass.h"
#include "passes/summed_area_pass.h"
#include "passes/traversal_pass.h"
#include "pipeline/pcss_settings.h"
#include "sampling/sample_table.h"
#include "reference/pcss_reference.h"
#include "scene/light_block.h"
#include "scene/scene.h"

namespace pn::glsl {
#include "exports/exact_pcss.h"
#include "exports/fast_pcss.h"
#include "exports/hqepcss.h"
#include "exports/pcf.h"
PN_STD140_SIZE(PnExactPcssExport, 32);
PN_STD140_OFFSET(PnExactPcssExport, bias, 24);
PN_STD140_SIZE(PnFastPcssExport, 80);
PN_STD140_OFFSET(PnFastPcssExport, grid, 64);
PN_STD140_SIZE(PnHqepcssExport, 64);
PN_STD140_OFFSET(PnHqepcssExport, nodeBudget, 48);
}  // namespace pn::glsl

namespace pn {
namespace {

constexpr int kMap = 64, kScreen = 48;  // brute force on the CPU stays fast

struct SceneImages {
  Image map, gbuffer;
  std::vector<ExportReceiver> receivers;  // every pixel that sees a surface, in row order
  std::vector<std::pair<int, int>> pixels;
};

SceneImages ray_cast(const Scene& scene) {
  SceneImages out{Image(kMap, kMap), Image(kScreen, kScreen, 4), {}, {}};
  for (int y = 0; y < kMap; ++y)
    for (int x = 0; x < kMap; ++x) out.map.at(x, y) = ray_cast_light_depth(scene, x, y);
  for (int y = 0; y < kScreen; ++y)
    for (int x = 0; x < kScreen; ++x) {
      const Receiver r = ray_cast_receiver(scene, x, y, kScreen);
      if (!r.valid) continue;
      const float v[4] = {float(r.u), float(r.v), float(r.depth), 1.0f};
      for (int c = 0; c < 4; ++c) out.gbuffer.at(x, y, c) = v[c];
      // The G-buffer's floats, as the reference reads them; every other receiver through the plane overload.
      out.receivers.push_back({v[0], v[1], v[2], out.receivers.size() % 2 == 1, 0.0f, 0.0f});
      out.pixels.push_back({x, y});
    }
  return out;
}

// The receivers' visibilities against the reference's on the screen (pixels without a surface
// are not receivers: they keep the reference's value).
CaseResult against(const std::string& name, const SceneImages& s, const PcssReference& reference,
                   const std::vector<float>& observed) {
  Image seen = reference.visibility;
  for (std::size_t k = 0; k < observed.size(); ++k) seen.at(s.pixels[k].first, s.pixels[k].second) = observed[k];
  const int ambiguous = leave_out_ambiguous(reference, seen);
  return {name + " (" + std::to_string(observed.size()) + " receivers, both overloads; " + std::to_string(ambiguous) +
              " pixels within rounding of a decision left out)",
          Tolerance::absolute(kFractionRounding),
          compare(reference.visibility, seen, Tolerance::absolute(kFractionRounding))};
}

// The settings pnFastPcss and pnHqepcss share, as they make the call exact PCSS (fast_pcss.glsl
// "Exactness"; the fast_pcss check's "hqepcss, refine 0, leaf 1, exact regions"): no refinement,
// exact regions, leaf 1, no budget; filter scale c.
template <class Block>
Block exact_settings_block(const LightModel& light, float bias, float c) {
  Block b{};
  set_light_fields(b, light);
  b.bias = bias;
  b.filterScale = c;
  b.refineIterations = 0;
  b.regionMode = PN_REGION_EXACT;
  b.leafSide = 1;
  b.leafDivisor = 0;
  b.nodeBudget = PN_TRAVERSAL_NO_BUDGET;
  return b;
}

// pnFastPcss's besides: the summed-area table's exact blocker sums, no grid.
glsl::PnFastPcssExport exact_fast_block(const LightModel& light, float bias, float c) {
  glsl::PnFastPcssExport b = exact_settings_block<glsl::PnFastPcssExport>(light, bias, c);
  b.leafMode = PN_LEAF_SAMPLED;
  b.blockerLeafMode = PN_FAST_PCSS_SAME_LEAF_MODE;
  b.depthSums = PN_DEPTH_SUMS_TABLE;
  b.grid = 0;
  return b;
}

}  // namespace

std::vector<CaseResult> run_exports_check(const CheckEnvironment& env) {
  const ExportPass exact(env.device, env.tree, "exact_pcss");
  const ExportPass pcf(env.device, env.tree, "pcf");
  const ExportPass fast(env.device, env.tree, "fast_pcss", {{"PN_EXPORT_SUM_TABLE", "1"}});
  const ExportPass hqepcss(env.device, env.tree, "hqepcss");
  const MinMaxMipBuilder mips(env.device, env.tree);
  const DepthPyramidBuilder pyramids(env.device, env.tree);
  const SummedAreaPass sums(env.device, env.tree);
  const std::unique_ptr<DeviceTexture> table = upload_sample_table(env.device, generate_sample_table(kSampleTableSeed));
  const float bias = exact_pcss().bias;
  std::vector<CaseResult> results;
  for (const auto& fixture : fixtures::kScenes) {
    const Scene scene = make_scene(fixture, kMap);
    const SceneImages s = ray_cast(scene);
    const std::unique_ptr<DeviceTexture> map = env.device.upload(s.map);
    const std::string name = std::string(fixture.name) + " " + std::to_string(kMap) + "² map, " +
                             std::to_string(kScreen) + "² screen: ";
    for (const float c : {1.0f, 0.5f}) {
      glsl::PnExactPcssExport block{};
      set_light_fields(block, scene.light);
      block.bias = bias;
      block.filterScale = c;
      const PcssReference reference = exact_pcss_reference(s.map, s.gbuffer, scene.light, bias, c, kPcssDecisionMargin);
      results.push_back(against(name + "exports/exact_pcss.comp (pnExactPcss, c " + format_number("%g", c) +
                                    ") vs exact PCSS brute force on the CPU",
                                s, reference, exact.run({{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, s.receivers,
                                                        query_block(block))));
    }
    const PcssReference exact_reference =
        exact_pcss_reference(s.map, s.gbuffer, scene.light, bias, 1.0, kPcssDecisionMargin);
    const DepthPyramid pyramid = pyramids.build(*map, kMap, kMap, 31);
    const glsl::PnHqepcssExport hqepcss_block = exact_settings_block<glsl::PnHqepcssExport>(scene.light, bias, 1.0f);
    results.push_back(against(name + "exports/hqepcss.comp (pnHqepcss: refine 0, exact regions, leaf 1) vs exact PCSS "
                                     "brute force on the CPU",
                              s, exact_reference,
                              hqepcss.run({{PN_EXPORT_PYRAMID_BINDING, *pyramid.texture},
                                           {PN_EXPORT_DEPTH_MAP_BINDING, *map}},
                                          s.receivers, query_block(hqepcss_block))));
    const MinMaxMipChain mip = mips.build(*map, kMap);
    const SummedAreaTable depth_sums = sums.build(*map, kMap, kMap);
    const glsl::PnFastPcssExport fast_block = exact_fast_block(scene.light, bias, 1.0f);
    results.push_back(
        against(name + "exports/fast_pcss.comp (pnFastPcss: refine 0, exact regions, leaf 1, table sums) vs exact PCSS "
                       "brute force on the CPU",
                s, exact_reference,
                fast.run({{PN_EXPORT_DEPTH_MAP_BINDING, *mip.texture},
                          {PN_EXPORT_SAMPLE_TABLE_BINDING, *table},
                          {PN_EXPORT_SUM_TABLE_BINDING, *depth_sums.texture}},
                         s.receivers, query_block(fast_block))));
    const glsl::PnPcfExport block{bias};
    const PcssReference reference =
        pcf_plane_reference(s.map, s.gbuffer, scene.light, bias, std::ldexp(1.0, -20), 0.0);
    results.push_back(against(name + "exports/pcf.comp (pnPcf) vs 2x2 bilinear PCF on the CPU", s, reference,
                              pcf.run({{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, s.receivers, query_block(block))));
  }
  return results;
}

}  // namespace pn
