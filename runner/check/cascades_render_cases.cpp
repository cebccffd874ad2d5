// The cascades check's rendering cases: the blend pass against the selection
// and blend in double, and the city's cascaded hard shadow against the
// ray-traced truth and its seams (tolerances: cascades_check.cpp).
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "cascades/cascade_fit.h"
#include "cascades/cascade_math.h"
#include "cascades/cascaded_frame.h"
#include "check/cascades_cases.h"
#include "check/device_scene.h"
#include "core/format.h"
#include "pass_runners/cascade_blend_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "reference/cascades_reference.h"
#include "scene/city_scene.h"
#include "technique/cascaded_technique.h"
#include "technique/technique_registry.h"
#include "truth/ray_traced_truth.h"

namespace pn {

// --- the blend pass: a technique's cascades into one visibility -------------------------------------------

// cascade_blend.comp over a screen of view depths (split ends, one ulp either side, band starts,
// uniform samples, pixels without a surface) and per-cascade visibilities of seeded noise,
// against the selection and blend in double. The weight's bound as in the selection cases.
void blend_pass_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const CascadeBlendPass pass(env.device, env.tree);
  const float near = 0.5f, far = 400.0f;
  const int size = 64;
  for (int count = 1; count <= PN_CASCADES_MAX; ++count) {
    CascadeSettings settings;
    settings.count = count;
    const std::vector<float> split_far = cascade_split_far(settings, near, far);
    std::mt19937 random(0xb1e0u + static_cast<unsigned>(count));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<float> depths;
    for (int i = 0; i < count; ++i) {
      const float end = split_far[static_cast<size_t>(i)], start = i == 0 ? near : split_far[static_cast<size_t>(i - 1)];
      const float band_start = static_cast<float>(end - settings.band * (static_cast<double>(end) - start));
      for (float z : {std::nextafter(end, 0.0f), end, std::nextafter(end, INFINITY), band_start, 0.5f * (band_start + end)})
        depths.push_back(z);
    }
    Image view_depth(size, size, 4, 0.0f);
    std::vector<Image> visibility(static_cast<size_t>(count), Image(size, size, 1));
    for (int k = 0; k < size * size; ++k) {
      const int x = k % size, y = k / size;
      const float z = k < static_cast<int>(depths.size()) ? depths[static_cast<size_t>(k)]
                                                          : static_cast<float>(0.4 * std::pow(1100.0, unit(random)));
      view_depth.at(x, y, 2) = z;
      view_depth.at(x, y, 3) = k % 17 == 5 ? 0.0f : 1.0f;  // some pixels see no surface
      for (Image& v : visibility) v.at(x, y) = static_cast<float>(unit(random));
    }
    const std::unique_ptr<DeviceTexture> view_texture = env.device.upload(view_depth);
    std::vector<std::unique_ptr<DeviceTexture>> textures;
    std::vector<const DeviceTexture*> pointers;
    for (const Image& v : visibility) pointers.push_back(textures.emplace_back(env.device.upload(v)).get());
    CascadeInputs inputs;
    inputs.layers.resize(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) inputs.split_far[i] = split_far[static_cast<size_t>(i)];
    inputs.near = near, inputs.band = static_cast<float>(settings.band);
    inputs.fade_last = count % 2 == 0;
    const Image observed = env.device.read_texture(*pass.blend(*view_texture, inputs, pointers, size));
    Image expected(size, size, 1);
    double narrowest = INFINITY;
    std::vector<double> split_far_d(split_far.begin(), split_far.end());
    for (int i = 0; i < count; ++i)
      narrowest = std::min(narrowest, settings.band * (split_far_d[static_cast<size_t>(i)] - (i == 0 ? near : split_far_d[static_cast<size_t>(i - 1)])));
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        if (view_depth.at(x, y, 3) == 0.0f) {
          expected.at(x, y) = 1.0f;
          continue;
        }
        const CascadeChoiceReference c = cascade_choice_reference(view_depth.at(x, y, 2), near, split_far_d, settings.band, inputs.fade_last);
        const auto value = [&](int cascade) { return cascade < count ? static_cast<double>(visibility[static_cast<size_t>(cascade)].at(x, y)) : 1.0; };
        expected.at(x, y) = static_cast<float>((1 - c.weight) * value(c.index) + c.weight * value(c.next));
      }
    const Tolerance tolerance = Tolerance::absolute(4 * kCascadeUlp * far / narrowest + 16 * kCascadeUlp);
    results.push_back({"blend pass, m " + std::to_string(count) + (inputs.fade_last ? ", last fades" : "") +
                           ": each pixel's visibility from its cascade and the next vs the definition",
                       tolerance, compare(expected, observed, tolerance)});
  }
}

namespace {

// --- the cascaded hard shadow on the city against the ray-traced truth -----------------------------------

// The share of light-facing pixels whose hard shadow (pcf, 2×2) differs from the truth's by more
// than half: the aliasing error of one map configuration.
double hard_shadow_mismatch(const Image& visibility, const Truth& truth) {
  long facing = 0, wrong = 0;
  for (int y = 0; y < visibility.height; ++y)
    for (int x = 0; x < visibility.width; ++x) {
      if (truth.faces_light.at(x, y) == 0.0f) continue;
      ++facing;
      wrong += std::fabs(visibility.at(x, y) - truth.visibility.at(x, y)) > 0.5f ? 1 : 0;
    }
  return facing > 0 ? static_cast<double>(wrong) / static_cast<double>(facing) : 0.0;
}

// What the city's cases share: the scene (its models read once) at 512² maps, and the passes
// that draw and blend its cascades.
struct CityRig {
  static constexpr int kMap = 512;
  explicit CityRig(const CheckEnvironment& env)
      : city(make_city_scene(fixtures::kCityScenes[0], kMap)),
        resources(env.device, env.tree),
        gbuffer(env.device, env.tree),
        maps(env.device, env.tree),
        blend(env.device, env.tree) {}
  const Scene city;
  TechniqueResources resources;
  const GBufferRenderer gbuffer;
  const ShadowMapRenderer maps;
  const CascadeBlendPass blend;
};

// The city under a point-like sun (1e-5 rad: penumbrae of 1e-5 of the blocker distance), 128²
// screen, 512² maps: the hard shadow of one map over the whole scene and of 1 to 4 cascades
// against the ray-traced truth (one sample a pixel). Cascades must alias less than the whole-
// scene map from two on (a single stable cascade is the whole frustum's sphere, wider than the
// scene's own box: measured 0.098 against 0.048), and 3 cascades less than 1.
void city_hard_shadow_cases(const CheckEnvironment& env, CityRig& rig, std::vector<CaseResult>& results) {
  constexpr int kScreen = 128, kMap = CityRig::kMap;
  Scene city = rig.city;
  light_by_sun(city, city.sun->direction, 1e-5);
  TruthSettings truth_settings;
  truth_settings.samples_per_side = 1;
  truth_settings.progress = false;
  const Truth truth = trace_truth(city, kScreen, truth_settings);
  const auto pcf = parse_technique("pcf")->create(rig.resources);
  const GBufferRenderer& gbuffer = rig.gbuffer;
  const DeviceSceneFrame whole = render_device_frame(env, city, kScreen);
  const double whole_error = hard_shadow_mismatch(env.device.read_texture(*pcf->run(whole.inputs, false).visibility), truth);
  std::vector<double> errors;
  for (int count = 1; count <= PN_CASCADES_MAX; ++count) {
    CascadeSettings settings;
    settings.count = count, settings.map_size = kMap;
    const auto frame = render_cascaded_frame(env.device, rig.maps, gbuffer, city, settings, kScreen);
    const CascadedTechnique on_cascades(*pcf, rig.blend, env.device);
    errors.push_back(hard_shadow_mismatch(
        env.device.read_texture(*on_cascades.run(frame->inputs(city.light), false).visibility),
        truth));
  }
  std::string table = "whole-scene map " + format_number("%.4f", whole_error);
  for (size_t m = 0; m < errors.size(); ++m) table += ", m " + std::to_string(m + 1) + " " + format_number("%.4f", errors[m]);
  // Each case holds when its excess is 0 (observed = how far the claim misses).
  for (size_t m = 1; m < errors.size(); ++m)  // one stable cascade spans the frustum's sphere: coarser than the scene's box
    results.push_back(row_case("city hard shadow vs the truth, share of light-facing pixels wrong (" + table + "): m " +
                                   std::to_string(m + 1) + " below the whole-scene map",
                               {0.0f}, {static_cast<float>(std::max(0.0, errors[m] - whole_error))}, Tolerance::exact()));
  results.push_back(row_case("city hard shadow: m 3 below m 1", {0.0f}, {static_cast<float>(std::max(0.0, errors[2] - errors[0]))},
                             Tolerance::exact()));

  // On cascades too, each cascade's call runs in the stage the frame asks for: Fast PCSS's and the
  // hard PCF's calls in fragment shaders equal their compute passes, blended.
  CascadeSettings three;
  three.count = 3, three.map_size = kMap;
  const auto frame = render_cascaded_frame(env.device, rig.maps, gbuffer, city, three, kScreen);
  for (const char* name : {"pcf", "fast"}) {
    const auto technique = parse_technique(name)->create(rig.resources);
    const CascadedTechnique on_cascades(*technique, rig.blend, env.device);
    TechniqueInputs inputs = frame->inputs(city.light);
    const Image computed = env.device.read_texture(*on_cascades.run(inputs, false).visibility);
    inputs.stage = ShadeStage::fragment;
    const Image fragment = env.device.read_texture(*on_cascades.run(inputs, false).visibility);
    results.push_back({std::string("city, 3 cascades: ") + name + "'s call in fragment shaders vs compute passes",
                       Tolerance::exact(), compare(computed, fragment, Tolerance::exact())});
  }
}

// --- no seams: Fast PCSS on cascades at the split borders ---------------------------------------------

// Over pairs of vertically neighbouring pixels whose view depths straddle split i's far end (p
// before it but inside the band, q after): how much more the blended visibility steps than cascade i + 1's own
// result steps between the same two pixels, mean of max(0, |out(q) - out(p)| - |v1(q) - v1(p)|).
// A seam is the step from one cascade's estimate to the next's; the band spreads it over its
// width, without it the whole difference falls between two pixels.
struct SeamMeasure {
  double excess = 0;
  long pairs = 0;
};

SeamMeasure seam_measure(const Image& out, const std::vector<Image>& layers, const Image& view_depth,
                         const std::vector<Cascade>& cascades) {
  SeamMeasure m;
  for (int y = 0; y + 1 < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      if (view_depth.at(x, y, 3) == 0.0f || view_depth.at(x, y + 1, 3) == 0.0f) continue;
      for (size_t i = 0; i + 1 < cascades.size(); ++i) {
        const float c = cascades[i].split_far;
        const float za = view_depth.at(x, y, 2), zb = view_depth.at(x, y + 1, 2);
        // Across the split, and p inside the band (where the next cascade holds it too): a silhouette
        // in front of the band is a depth edge, not a seam.
        if ((za < c) == (zb < c) || za < cascades[i + 1].fit_near) continue;
        const Image& next = layers[i + 1];
        const double step = std::fabs(out.at(x, y + 1) - out.at(x, y));
        const double own = std::fabs(next.at(x, y + 1) - next.at(x, y));
        m.excess += std::max(0.0, step - own), ++m.pairs;
      }
    }
  if (m.pairs > 0) m.excess /= static_cast<double>(m.pairs);
  return m;
}

// The city, 192² screen, 3 cascades of 512² (fitted with the band 0.1), Fast PCSS on each; the
// layers blended with the band and, for the record, with band 0 (the same maps and layers: only
// the blend differs). With the band the borders' mean excess step must stay below 0.02 — a
// visible seam is the difference between two cascades' estimates, tenths — (measured 0.0054;
// the same without the band: on this view the cascades agree at their borders, and it is the
// blend-pass cases that prove the band continuous where they do not).
void seam_cases(const CheckEnvironment& env, CityRig& rig, std::vector<CaseResult>& results) {
  constexpr int kScreen = 192;
  const Scene& city = rig.city;
  const auto fast = parse_technique("fast")->create(rig.resources);
  const CascadeBlendPass& blend = rig.blend;
  CascadeSettings settings;
  settings.count = 3, settings.map_size = CityRig::kMap;
  const auto frame = render_cascaded_frame(env.device, rig.maps, rig.gbuffer, city, settings, kScreen);
  std::vector<TechniqueFrame> runs;
  for (const TechniqueInputs& layer : frame->layers.layers) runs.push_back(fast->run(layer, false));
  std::vector<const DeviceTexture*> visibilities;
  std::vector<Image> layers;
  for (const TechniqueFrame& run : runs) {
    visibilities.push_back(run.visibility.get());
    layers.push_back(env.device.read_texture(*run.visibility));
  }
  const Image view_depth = env.device.read_texture(*frame->view_depth);
  SeamMeasure measures[2];
  for (int b = 0; b < 2; ++b) {
    CascadeInputs inputs = frame->layers;
    inputs.band = b == 0 ? static_cast<float>(settings.band) : 0.0f;
    const Image out = env.device.read_texture(*blend.blend(inputs, visibilities, kScreen));
    measures[b] = seam_measure(out, layers, view_depth, frame->cascades);
  }
  const std::string numbers = "band 0.1: " + format_number("%.4f", measures[0].excess) + " over " +
                              std::to_string(measures[0].pairs) + " border pairs, no band: " +
                              format_number("%.4f", measures[1].excess);
  results.push_back(row_case("no seams: Fast PCSS on 3 cascades of the city, the step across split borders beyond the next "
                             "cascade's own (" + numbers + "): with the band < 0.02",
                             {0.0f}, {static_cast<float>(std::max(0.0, measures[0].excess - 0.02))},
                             Tolerance::exact()));
  results.push_back(row_case("no seams: the city's split borders are crossed by some pixel pairs (> 50)", {0.0f},
                             {measures[0].pairs > 50 ? 0.0f : 1.0f}, Tolerance::exact()));
}

}  // namespace

void city_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  CityRig rig(env);
  city_hard_shadow_cases(env, rig, results);
  seam_cases(env, rig, results);
}

}  // namespace pn
