// The pcss_regions check's cases on rendered scenes: the tall blocker's own map and
// G-buffer in every mode, the lit-coverage property there and on the boxes'
// far field (pcss_regions_check.cpp states the tolerances).
#include <array>
#include <memory>
#include <utility>

#include "check/pcss_regions_cases.h"
#include "scenes.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/gbuffer_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "pipeline/pcss_settings.h"
#include "scene/scene.h"

namespace pn {
namespace {

using namespace pcss_regions_cases;

struct SceneData {
  std::string name;
  LightModel light;
  Image map, gbuffer;
  DepthPyramid pyramid;
  std::unique_ptr<DeviceTexture> map_texture;  // what `mip` was built from (MinMaxMipChain::map)
  MinMaxMipChain mip;
  std::vector<RegionReceiver> receivers;
};

SceneData scene_data(const CheckEnvironment& env, const char* scene_name, int map_size = kSceneMap,
                     int screen_size = kSceneScreen) {
  const Scene scene = make_scene(find_scene_fixture(scene_name), map_size);
  // The scene's map and G-buffer as a frame renders them (render_scene_frame), on the executor.
  std::unique_ptr<DeviceTexture> map = ShadowMapRenderer(env.device, env.tree).render_texture(scene, scene.map_light());
  const std::unique_ptr<DeviceTexture> gbuffer = GBufferRenderer(env.device, env.tree)
                                                     .render_texture(scene, screen_size, fixtures::kNormalOffsetTexels,
                                                                     scene.map_light());
  SceneData s;
  s.name = std::string(scene_name) + " " + std::to_string(map_size) + "² map, " + std::to_string(screen_size) + "² screen";
  s.light = scene.light;
  s.map = env.device.read_texture(*map);
  s.gbuffer = env.device.read_texture(*gbuffer);
  s.pyramid = DepthPyramidBuilder(env.device, env.tree).build(*map, map_size, map_size, 31);
  s.mip = MinMaxMipBuilder(env.device, env.tree).build(*map, map_size);
  s.map_texture = std::move(map);
  for (int y = 0; y < screen_size; ++y)
    for (int x = 0; x < screen_size; ++x)
      s.receivers.push_back({s.gbuffer.at(x, y, 0), s.gbuffer.at(x, y, 1), s.gbuffer.at(x, y, 2), s.gbuffer.at(x, y, 3)});
  return s;
}

}  // namespace

LitCoverage pcss_regions_lit_coverage(const CheckEnvironment& env, RegionMode mode, const char* scene_name) {
  const PcssRegionsQueryPass pass(env.device, env.tree);
  const bool boxes = std::string(scene_name) == "boxes";
  const SceneData scene = boxes ? scene_data(env, scene_name, kBoxesMap, kBoxesScreen) : scene_data(env, scene_name);
  const PcssSettings defaults;
  const std::vector<PcssRegionsResult> observed =
      pass.run(scene.pyramid, scene.light, search_queries(scene.receivers, mode, defaults.refine_iterations, defaults.bias));
  return count_lit_coverage(scene.name + ", " + mode_name(mode) + ", " + std::to_string(defaults.refine_iterations) +
                                " iterations",
                            scene.receivers,
                            shadowing_truths(DepthScan(scene.map), scene.light, scene.receivers, defaults.bias),
                            observed);
}

void pcss_regions_cases::scene_cases(const CheckEnvironment& env, const PcssRegionsQueryPass& pass,
                                     std::vector<CaseResult>& results, SearchTally& tally) {
  // The tall-blocker scene's own shadow map and G-buffer, the pipeline's bias.
  const SceneData scene = scene_data(env, "tall_blocker");
  const DepthScan scan(scene.map);
  const PcssSettings defaults;
  const std::vector<ShadowingTruth> truths = shadowing_truths(scan, scene.light, scene.receivers, defaults.bias);
  struct SceneSearch {
    RegionMode mode;
    Structure structure;
    bool area_edges;  // PN_AREA_EDGES (issue 51): the search reads the min over each square's cover
  };
  // The squares with area-weighted edges: the pass compiled with the option, its entries against the
  // reference reading area_cover (the decisions stay conservative), pnEntryRect = the cover.
  const PcssRegionsQueryPass area_pass(env.device, env.tree, true);
  for (const SceneSearch& search : {SceneSearch{RegionMode::window, Structure::pyramid, false},
                                    SceneSearch{RegionMode::exact, Structure::pyramid, false},
                                    SceneSearch{RegionMode::centred, Structure::pyramid, false},
                                    SceneSearch{RegionMode::exact, Structure::mip, false},
                                    SceneSearch{RegionMode::exact, Structure::mip, true}}) {
    const RegionMode mode = search.mode;
    const std::string what = search.area_edges                     ? "the mip chain's search over squares with area-weighted edges"
                             : search.structure == Structure::mip ? "the mip chain's search"
                                                                  : mode_name(mode);
    EntryGroup g;
    for (int iterations : {0, defaults.refine_iterations}) {
      const std::vector<PcssRegionsResult> observed =
          (search.area_edges ? area_pass : pass)
              .run(scene.pyramid, scene.light,
                   search_queries(scene.receivers, mode, iterations, defaults.bias, search.structure), &scene.mip);
      for (size_t k = 0; k < scene.receivers.size(); ++k) {
        Rounding rounding{kAmbiguity};
        const RegionEntry expected = search_entry(scan, scene.light, scene.receivers[k], defaults.bias, iterations,
                                                  &rounding, search.structure, nullptr, search.area_edges);
        add_entry(g, expected, rounding.ambiguous, observed[k]);
        add_regions(g, observed[k], kSceneMap, mode, search.area_edges);
      }
      if (iterations > 0)
        results.push_back(count_lit_coverage(scene.name + ", " + what + ", " + std::to_string(iterations) + " iterations",
                                             scene.receivers, truths, observed)
                              .result);
    }
    tally.searched += g.queries, tally.left_out += g.left_out;
    push_group(results, scene.name + ", " + what, g,
               ("search entries (0 and " + std::to_string(defaults.refine_iterations) + " iterations)").c_str());
  }

  // The search with a receiver plane (pnSearchEntryMipPlane, as Fast PCSS's Step 3 calls it): each
  // receiver with a gradient of its own, of either sign and unequal in u and v. The plane's highest
  // threshold over a square about its receiver is the receiver's own (capped there) but for a square
  // under 2 texels a side — so the plane changes next to no entry; a centre read (v, u) moves the
  // square off it, where steep gradients decide receivers lit. Against search_entry with that gradient.
  {
    std::vector<PcssRegionsQuery> queries =
        search_queries(scene.receivers, RegionMode::exact, defaults.refine_iterations, defaults.bias, Structure::mip);
    const auto gradient = [](std::size_t k) {
      return std::array<float, 2>{0.04f * static_cast<float>(static_cast<int>(k % 5) - 2),
                                  0.11f * static_cast<float>(static_cast<int>(k % 3) - 1)};
    };
    // Every other query over the pyramid (pnSearchEntryPlane: no count of its refinements).
    const auto structure = [](std::size_t k) { return k % 2 == 0 ? Structure::mip : Structure::pyramid; };
    for (std::size_t k = 0; k < queries.size(); ++k)
      queries[k].kind = structure(k) == Structure::mip ? PcssRegionsQuery::Kind::search_mip_plane
                                                       : PcssRegionsQuery::Kind::search_plane,
      queries[k].gradient = gradient(k);
    const std::vector<PcssRegionsResult> observed = pass.run(scene.pyramid, scene.light, queries, &scene.mip);
    EntryGroup g;
    int changed = 0;  // entries the plane changes (lit, or refined less far)
    for (std::size_t k = 0; k < scene.receivers.size(); ++k) {
      Rounding rounding{kAmbiguity};
      int refinements = 0;
      const RegionEntry expected =
          search_entry(scan, scene.light, scene.receivers[k], defaults.bias, defaults.refine_iterations, &rounding,
                       structure(k), &refinements, false, {gradient(k)[0], gradient(k)[1]});
      add_entry(g, expected, rounding.ambiguous, observed[k], structure(k) == Structure::mip ? refinements : -1);
      const RegionEntry flat = search_entry(scan, scene.light, scene.receivers[k], defaults.bias,
                                            defaults.refine_iterations, nullptr, structure(k));
      if (expected.lit() != flat.lit() || (!expected.lit() && expected.side != flat.side)) ++changed;
    }
    tally.searched += g.queries, tally.left_out += g.left_out;
    push_group(results, scene.name + ", the mip chain's and the pyramid's search with a receiver plane (" + std::to_string(changed) +
                            " entries differ from the flat search's)",
               g, ("search entries and refinements (" + std::to_string(defaults.refine_iterations) + " iterations)").c_str());
  }

  // The property on the boxes scene at render's resolution, on the far field (screen rows 128-319,
  // where the far boxes' walls are), for the paper's window mode and the shipped search over the mip
  // chain: those walls are where the paper's lit decision scribbled (issue 11 item 6). Not with
  // --quick: the passes above ran these programs, and the brute-force truth of 98,304 receivers
  // is most of the check's time.
  if (!env.options.quick) {
    SceneData boxes = scene_data(env, "boxes", kBoxesMap, kBoxesScreen);
    boxes.receivers.erase(boxes.receivers.begin() + 320 * kBoxesScreen, boxes.receivers.end());
    boxes.receivers.erase(boxes.receivers.begin(), boxes.receivers.begin() + 128 * kBoxesScreen);
    const std::vector<ShadowingTruth> boxes_truths =
        shadowing_truths(DepthScan(boxes.map), boxes.light, boxes.receivers, defaults.bias);
    for (const SceneSearch& search : {SceneSearch{RegionMode::window, Structure::pyramid, false},
                                      SceneSearch{RegionMode::exact, Structure::mip, false}}) {
      const std::string what = search.structure == Structure::mip ? "the mip chain's search" : mode_name(search.mode);
      const std::vector<PcssRegionsResult> observed = pass.run(
          boxes.pyramid, boxes.light,
          search_queries(boxes.receivers, search.mode, defaults.refine_iterations, defaults.bias, search.structure),
          &boxes.mip);
      results.push_back(count_lit_coverage(boxes.name + " (rows 128-319: the far field), " + what + ", " +
                                               std::to_string(defaults.refine_iterations) + " iterations",
                                           boxes.receivers, boxes_truths, observed)
                            .result);
    }
  }
}

}  // namespace pn
