// Cases of the pipeline check (issue 5): every registry technique through the
// seam (finite, the sky lit, and its one call in a fragment shader equal to
// its own path); the hard shadow with the G-buffer's receiver planes
// (pcf:receiver-plane=on) against the CPU's; exact PCSS against the CPU reference; the wiring check (Fast PCSS with every improvement off equals
// exact PCSS); SSIM of Fast PCSS with the paper's defaults against exact
// PCSS at 512²; and bad inputs — NaN and empty shadow-map texels, receivers
// outside the light's frustum, a zero-size light — giving finite, documented
// results.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "check/blur_tolerance.h"
#include "check/device_scene.h"
#include "check/module_check.h"
#include "check/pcss_compare.h"
#include "metrics/lit_image.h"
#include "gl/texture.h"
#include "pass_runners/surface_pass.h"
#include "metrics/ssim.h"
#include "pass_runners/gbuffer_pass.h"
#include "pipeline/pcss_pipeline.h"
#include "reference/blur_reference.h"
#include "reference/pcss_reference.h"
#include "reference/depth_pyramid_reference.h"
#include "reference/reuse_reference.h"
#include "frame/scene_frame.h"
#include "technique/technique_registry.h"

namespace pn {
namespace {

constexpr int kMap = 128, kScreen = 64;     // small: brute force on llvmpipe stays fast
constexpr double kMinimumSsim = 0.97;       // seed 000 Table / §5.4 reports 0.9705

Image read(const QueryDevice& d, const DeviceTexture& t) { return d.read_texture(t, 0, 0); }

// A scalar as a 1×1 comparison: expected `target`, observed `value`, passing within `bound`.
CaseResult scalar_case(const std::string& name, double target, double value, Tolerance tolerance) {
  Image e(1, 1, 1, static_cast<float>(target)), o(1, 1, 1, static_cast<float>(value));
  return {name, tolerance, compare(e, o, tolerance)};
}

// Pixels that see no surface (G-buffer w = 0) must be exactly 1 (lit); elsewhere the image's own value.
CaseResult sky_stays_lit(const std::string& name, const Image& gbuffer, const Image& visibility) {
  Image expected = visibility;
  int sky = 0;
  for (int y = 0; y < visibility.height; ++y)
    for (int x = 0; x < visibility.width; ++x)
      if (gbuffer.at(x, y, 3) == 0.0f) expected.at(x, y) = 1.0f, ++sky;
  return {name + " (" + std::to_string(sky) + " pixels)", Tolerance::exact(), compare(expected, visibility, Tolerance::exact())};
}

// The depth Step 6's blur cuts at, from the G-buffer on the CPU: the receiver's light depth, +Inf where none.
Image receiver_depths(const Image& gbuffer) {
  Image out(gbuffer.width, gbuffer.height);
  for (int y = 0; y < gbuffer.height; ++y)
    for (int x = 0; x < gbuffer.width; ++x)
      out.at(x, y) = gbuffer.at(x, y, 3) != 0.0f && std::isfinite(gbuffer.at(x, y, 2)) ? gbuffer.at(x, y, 2) : INFINITY;
  return out;
}

// Every texel finite and in [0, 1]: the image must equal itself clamped to
// [0, 1], with every non-finite texel replaced by -1.
CaseResult in_unit_range(const std::string& name, const Image& image) {
  Image expected = image;
  for (float& v : expected.texels) v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : -1.0f;
  return {name, Tolerance::exact(), compare(expected, image, Tolerance::exact())};
}

// The hard shadow of a point light at the map's centre of projection: the texel under (u, v).
Image hard_shadow(const Image& shadow_map, const Image& gbuffer, double bias) {
  Image out(gbuffer.width, gbuffer.height, 1, 1.0f);
  const int n = shadow_map.width;
  for (int y = 0; y < gbuffer.height; ++y)
    for (int x = 0; x < gbuffer.width; ++x) {
      const double u = gbuffer.at(x, y, 0), v = gbuffer.at(x, y, 1), d = gbuffer.at(x, y, 2);
      if (gbuffer.at(x, y, 3) == 0.0f || !(u >= 0 && u < n && v >= 0 && v < n)) continue;
      const double z = sanitize_depth(shadow_map.at(static_cast<int>(u), static_cast<int>(v)));
      if (z < d - bias) out.at(x, y) = 0.0f;
    }
  return out;
}

// The reuse scheme on a scene's own maps (Steps 4 and 5 of `frame`): the GPU's
// parent codes against the CPU's parents of the same link keys, exactly; every
// group inside one k×k tile; and, for Step 5, every pixel's visibility equal to
// its representative's.
void reuse_cases(const QueryDevice& context, const std::string& name, const PcssFrame& frame, std::vector<CaseResult>& out) {
  const int n = frame.size;
  const PcssSettings& s = frame.settings;
  struct Step {
    const char* what;
    const DeviceTexture& keys;
    const PcssFrame::Texture& parents;
    int tile;
    bool shades;  // Step 5: its representatives' results are the visibility
  };
  for (const Step& step : {Step{"Step 4", frame.search_reuse_keys(), frame.search_parents, s.search_tile, false},
                           Step{"Step 5", frame.filter_reuse_keys(), frame.filter_parents, s.filter_tile, true}}) {
    ReuseParams params;
    params.sigma1 = s.sigma1, params.sigma2 = s.sigma2, params.sigma3 = s.sigma3, params.tile = step.tile;
    const std::vector<int> parents = reuse_parents(read(context, step.keys), params);
    const std::vector<int> roots = reuse_roots(parents);
    const Image codes = read(context, *step.parents);
    Image expected(n, n), tiles(n, n), same_tile(n, n, 1, 1.0f);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const int i = y * n + x, p = parents[i];
        expected.at(x, y) = p < 0 ? 0.0f : p == i - 1 ? 1.0f : 2.0f;  // reuse.glsl's codes: none, left, top
        const int r = roots[i], rx = r % n, ry = r / n;
        tiles.at(x, y) = (rx / step.tile == x / step.tile && ry / step.tile == y / step.tile) ? 1.0f : 0.0f;
      }
    out.push_back({name + ": " + step.what + " reuse links (k = " + std::to_string(step.tile) +
                       ") on the scene's own map vs the CPU's parents",
                   Tolerance::exact(), compare(expected, codes, Tolerance::exact())});
    out.push_back({name + ": " + step.what + " every group inside its k x k tile (1 = inside)", Tolerance::exact(),
                   compare(same_tile, tiles, Tolerance::exact())});
    if (step.shades) {
      const Image visibility = read(context, *frame.visibility);
      Image of_root(n, n);
      for (int i = 0; i < n * n; ++i) of_root.at(i % n, i / n) = visibility.at(roots[i] % n, roots[i] / n);
      out.push_back({name + ": Step 5 every pixel's visibility equals its representative's", Tolerance::exact(),
                     compare(of_root, visibility, Tolerance::exact())});
    }
  }
}

// Every registry entry through the technique seam, and the hard shadow with the G-buffer's
// receiver planes, on the scene's own maps.
void technique_cases(const QueryDevice& context, TechniqueResources& resources, const std::string& name,
                     const Scene& scene, const TechniqueInputs& inputs, const Image& map, const Image& gbuffer,
                     std::vector<CaseResult>& results) {
  // Every registry entry: a visibility image, finite and in [0, 1],
  // exactly 1 where the pixel sees no surface (no shadow on the sky).
  // Its one call in a fragment shader (a full-screen triangle reading the G-buffer, as a deferred
  // lighting pass runs it) against the runner's path: the same arithmetic, equal on llvmpipe.
  const auto one_call_case = [&](const std::string& technique_name, const Technique& technique, const Image& visibility) {
    if (!technique.has_one_call()) return;
    TechniqueInputs fragment_inputs = inputs;
    fragment_inputs.stage = ShadeStage::fragment;
    results.push_back({name + ": technique '" + technique_name + "': its one call in a fragment shader vs its own path",
                       Tolerance::exact(),
                       compare(visibility, context.read_texture(*technique.run(fragment_inputs, false).visibility, 0, 0),
                               Tolerance::exact())});
  };
  for (const TechniqueEntry& entry : technique_registry()) {
    const std::unique_ptr<Technique> technique = entry.make()->create(resources);
    const Image visibility = context.read_texture(*technique->run(inputs, true).visibility, 0, 0);
    results.push_back(in_unit_range(name + ": technique '" + entry.name + "' through the seam: finite, in [0, 1]", visibility));
    results.push_back(sky_stays_lit(name + ": technique '" + entry.name + "': pixels that see no surface stay lit",
                                    gbuffer, visibility));
    one_call_case(entry.name, *technique, visibility);
  }
  // A setting no registry row has whose call takes another walk than the shipped settings': HQEPCSS's
  // node budget (PN_HQEPCSS_ABLATIONS: traversal_pyramid.glsl's walk). Leaves of one texel and a
  // budget of two nodes: it binds in every window wider than a texel (the root's first child and
  // every node after it estimated at their min).
  for (const char* spec : {"hqepcss:leaf=1:budget=2"}) {
    const std::unique_ptr<Technique> technique = parse_technique(spec)->create(resources);
    one_call_case(spec, *technique, context.read_texture(*technique->run(inputs, true).visibility, 0, 0));
  }

  // The hard shadow with the receiver plane from the G-buffer (pcf:receiver-plane=on) in both stages
  // against the CPU's bilinear PCF with the same planes, ambiguous pixels left out; and a shallow
  // slope clamp, tangent 0.5, with a small bias (gbuffer_receiver_plane.glsl's plane is there for any
  // tangent > 0: the boxes' sloped receivers clamp to it, and without it their texels shadow them).
  struct PlaneCase {
    const char* technique;
    double bias, tangent;
    bool fragment;
  };
  for (const PlaneCase& c : {PlaneCase{"pcf:receiver-plane=on:bias=0.01", 0.01, kReceiverPlaneTan, true},
                             PlaneCase{"pcf:receiver-plane=0.5:bias=0.002", 0.002, 0.5, false}}) {
    const std::unique_ptr<Technique> pcf = parse_technique(c.technique)->create(resources);
    const PcssReference reference = pcf_plane_reference(map, gbuffer, scene.light, c.bias, std::ldexp(1.0, -20), c.tangent);
    TechniqueInputs fragment_inputs = inputs;
    fragment_inputs.stage = ShadeStage::fragment;
    std::vector<const TechniqueInputs*> stages{&inputs};
    if (c.fragment) stages.push_back(&fragment_inputs);
    for (const TechniqueInputs* stage : stages) {
      Image observed = context.read_texture(*pcf->run(*stage, false).visibility, 0, 0);
      const int ambiguous = leave_out_ambiguous(reference, observed);
      results.push_back({name + ": " + c.technique + ", " +
                             (stage->stage == ShadeStage::fragment ? "fragment shader" : "compute pass") +
                             ", vs 2x2 bilinear PCF with the G-buffer's planes on the CPU (" +
                             std::to_string(ambiguous) + " pixels within rounding of a decision left out)",
                         Tolerance::absolute(kFractionRounding),
                         compare(reference.visibility, observed, Tolerance::absolute(kFractionRounding))});
    }
  }
}

}  // namespace

std::vector<CaseResult> run_pipeline_check(const CheckEnvironment& env) {
  const QueryDevice& context = env.device;
  const PcssPipeline pipeline(context, env.tree);
  TechniqueResources resources(context, env.tree);
  std::vector<CaseResult> results;
  // The second layers the registry's entries ask for (back-projection's back-face layer).
  std::vector<std::unique_ptr<TechniqueConfig>> entries;
  std::vector<const TechniqueConfig*> configs;
  for (const TechniqueEntry& entry : technique_registry()) configs.push_back(entries.emplace_back(entry.make()).get());
  const std::vector<MapLayer> layers = second_layers_of(configs);
  for (const auto& fixture : check_scenes(env)) {
    const Scene scene = make_scene(fixture, kMap);
    const std::string name = std::string(fixture.name) + " " + std::to_string(kMap) + "² map, " +
                             std::to_string(kScreen) + "² screen";
    const DeviceSceneFrame frame = render_device_frame(env, scene, kScreen, layers);
    const TechniqueInputs& inputs = frame.inputs;
    const Image map = read(context, *frame.shadow_map), gbuffer = read(context, *frame.gbuffer);

    technique_cases(context, resources, name, scene, inputs, map, gbuffer, results);

    // Exact PCSS (its default: the squares with area-weighted edges, issue 51) against the CPU's
    // definition, ambiguous pixels left out (counted in the name); the integer squares: the
    // fast_pcss check and the zero-size light below.
    const PcssSettings exact = exact_pcss();
    const PcssFrame exact_frame = pipeline.run(inputs, exact);
    const Image exact_visibility = read(context, exact_frame.soft_shadow());
    const Tolerance area_rounding = Tolerance::absolute(area_edges_rounding(kMap));
    const auto area_reference = [&](const Image& shadow_map, const Image& receivers, const LightModel& light) {
      return exact_pcss_area_reference(shadow_map, receivers, light, exact.bias, exact.filter_scale, kAreaEdgeMargin);
    };
    const PcssReference reference = area_reference(map, gbuffer, scene.light);
    Image observed = exact_visibility;
    const int ambiguous = leave_out_ambiguous(reference, observed);
    results.push_back({name + ": exact PCSS vs CPU brute force (" + std::to_string(ambiguous) + " pixels within rounding of a decision left out)",
                       area_rounding, compare(reference.visibility, observed, area_rounding)});

    // The wiring check: every improvement off. The blocker mean is summed in another order, so a
    // pixel may differ where the two blocker means differ (by float rounding, checked) and move a
    // filter square; the areas too, within their rounding (area_edges_rounding).
    PcssSettings off = fast_pcss_all_off();
    off.staged = true;  // its blocker means, Step 4's output (the one call's: the fast_pcss check)
    const PcssFrame off_frame = pipeline.run(inputs, off);
    const Image off_visibility = read(context, off_frame.soft_shadow());
    const Image exact_mean = read(context, *exact_frame.blocker_mean);
    const Image off_mean = read(context, *off_frame.blocker_mean);
    results.push_back({name + ": blocker mean, all improvements off vs exact PCSS", Tolerance::relative(1e-5),
                       compare(exact_mean, off_mean, Tolerance::relative(1e-5))});
    Image aligned = off_visibility;
    int moved = 0;
    for (int y = 0; y < kScreen; ++y)
      for (int x = 0; x < kScreen; ++x)
        if (exact_mean.at(x, y) != off_mean.at(x, y) && aligned.at(x, y) != exact_visibility.at(x, y))
          aligned.at(x, y) = exact_visibility.at(x, y), ++moved;
    results.push_back({name + ": soft shadow, all improvements off vs exact PCSS (" + std::to_string(moved) +
                           " pixels whose blocker mean rounded apart left out)",
                       area_rounding, compare(exact_visibility, aligned, area_rounding)});

    // The reuse scheme and the fixed-radius blur of the paper's settings (fast-paper), and the
    // adaptive blur of fast-blur: each on the scene's own maps.
    const PcssFrame fast_frame = pipeline.run(inputs, fast_paper_pcss());
    reuse_cases(context, name, fast_frame, results);

    // Step 6 cuts at the G-buffer's depth edges and at pixels without a surface: Fast PCSS's blurred map
    // equals the CPU's depth-aware blur of its unblurred map over the G-buffer's receiver depths.
    {
      const BlurParams& blur = fast_frame.settings.blur_params;
      const Image unblurred = read(context, *fast_frame.visibility);
      const Image expected = blur_depth_aware_reference(unblurred, receiver_depths(gbuffer), blur);
      const Tolerance tolerance = blur_tolerance(blur, unblurred);
      results.push_back({name + ": fast-paper's Step 6 vs the depth-aware blur over the G-buffer's receiver depths",
                         tolerance, compare(expected, read(context, *fast_frame.blurred), tolerance)});
      PcssSettings adaptive = fast_pcss();
      adaptive.blur = true;  // fast-blur
      const PcssFrame adaptive_frame = pipeline.run(inputs, adaptive);
      const Image adaptive_unblurred = read(context, *adaptive_frame.visibility);
      const Image depths = receiver_depths(gbuffer);
      const Image adaptive_expected = blur_adaptive_reference(adaptive_unblurred, read(context, *adaptive_frame.filter_map),
                                                              &depths, adaptive_frame.settings.blur_params);
      const Tolerance adaptive_tolerance = blur_tolerance(adaptive_frame.settings.blur_params, adaptive_unblurred);
      results.push_back({name + ": fast-blur's Step 6 vs the adaptive depth-aware blur (radius from each filter side)",
                         adaptive_tolerance,
                         compare(adaptive_expected, read(context, *adaptive_frame.blurred), adaptive_tolerance)});
    }
    const Image listed = read(context, fast_frame.soft_shadow());
    PcssSettings branch = fast_paper_pcss();
    branch.skip = WorkSkip::branch;
    const Image branched = read(context, pipeline.run(inputs, branch).soft_shadow());
    results.push_back({name + ": fast-paper, representatives compacted into a list vs branching in place",
                       Tolerance::exact(), compare(listed, branched, Tolerance::exact())});

    // Bad inputs on this scene: NaN and +Inf texels; receivers pushed outside the frustum.
    Image damaged = map;
    for (int y = 0; y < kMap; ++y)
      for (int x = 0; x < kMap; ++x)
        if ((x * 7 + y * 3) % 11 == 0) damaged.at(x, y) = NAN;
        else if (x > kMap / 2 && y > kMap / 2 && (x + y) % 5 == 0) damaged.at(x, y) = INFINITY;
    Image outside = gbuffer;
    for (int y = 0; y < kScreen; ++y)
      for (int x = 0; x < kScreen / 2; ++x) outside.at(x, y, 0) += (y % 2 ? 3.0f : -3.0f) * kMap;
    const std::unique_ptr<DeviceTexture> damaged_map = context.upload(damaged), outside_gbuffer = context.upload(outside);
    TechniqueInputs bad = inputs;
    bad.shadow_map = damaged_map.get();
    bad.gbuffer = outside_gbuffer.get();
    const PcssReference bad_reference = area_reference(damaged, outside, scene.light);
    Image bad_observed = read(context, pipeline.run(bad, exact).soft_shadow());
    leave_out_ambiguous(bad_reference, bad_observed);
    results.push_back({name + ": exact PCSS, NaN/+Inf texels (no occluder) and receivers outside the frustum (lit)",
                       area_rounding, compare(bad_reference.visibility, bad_observed, area_rounding)});
    results.push_back(in_unit_range(name + ": Fast PCSS, NaN/+Inf texels and receivers outside the frustum: finite, in [0, 1]",
                                    read(context, pipeline.run(bad, fast_pcss()).soft_shadow())));

    // A zero-size light: every region one texel wide — over the integer squares (edges=texel) the
    // texel under the receiver, a hard shadow; over the default squares with area-weighted edges
    // the texels a one-texel square about it overlaps, each by its overlap (the definition).
    Scene point = scene;
    point.light.width = 0.0;
    const DeviceSceneFrame point_frame = render_device_frame(env, point, kScreen);
    const TechniqueInputs& point_inputs = point_frame.inputs;
    const Image point_map = read(context, *point_frame.shadow_map), point_gbuffer = read(context, *point_frame.gbuffer);
    const Image hard = hard_shadow(point_map, point_gbuffer, exact.bias);
    const PcssReference one_texel = area_reference(point_map, point_gbuffer, point.light);
    for (PcssSettings s : {exact, fast_pcss()}) {  // fast: exact regions, no blur
      Image area = read(context, pipeline.run(point_inputs, s).soft_shadow());
      const int left_out = leave_out_ambiguous(one_texel, area);
      results.push_back({name + ", zero-size light: " + s.name + " vs a one-texel square's area-weighted texels (" +
                             std::to_string(left_out) + " pixels within rounding of a decision left out)",
                         area_rounding, compare(one_texel.visibility, area, area_rounding)});
      s.edges = false;
      results.push_back({name + ", zero-size light: " + s.name + ", edges=texel vs the hard shadow", Tolerance::exact(),
                         compare(hard, read(context, pipeline.run(point_inputs, s).soft_shadow()), Tolerance::exact())});
    }
    results.push_back(in_unit_range(name + ", zero-size light: fast-paper (2x2-texel windows): finite, in [0, 1]",
                                    read(context, pipeline.run(point_inputs, fast_paper_pcss()).soft_shadow())));
  }

  // The paper's quality claim (§5.4: SSIM of the rendered pictures) on the default
  // scene at 512²: the lit images' SSIM is held to 0.97; the soft-shadow maps'
  // own SSIM, lower (docs/pipeline.md says why), is printed with it. Not with --quick: the
  // same programs ran above, and 512² of exact PCSS is most of the check's time on lavapipe.
  if (env.options.quick) return results;
  const Scene scene = make_scene(fixtures::kScenes[0], 512);
  const DeviceSceneFrame frame = render_device_frame(env, scene, 512);
  const TechniqueInputs& inputs = frame.inputs;
  const Image surface = read(context, *SurfaceRenderer(context, env.tree).render_texture(scene, 512));
  const Image exact = read(context, pipeline.run(inputs, exact_pcss()).soft_shadow());
  for (const PcssSettings& s : {fast_pcss(), fast_paper_pcss(), hqepcss()}) {
    const Image shadow = read(context, pipeline.run(inputs, s).soft_shadow());
    char map_ssim[32];
    std::snprintf(map_ssim, sizeof map_ssim, "%.4f", ssim(exact, shadow));
    results.push_back(scalar_case(std::string(fixtures::kScenes[0].name) + " 512²: SSIM of " + s.name +
                                      "'s lit image vs exact PCSS's >= 0.97, expected 1 (soft-shadow maps: " + map_ssim + ")",
                                  1.0, lit_ssim(surface, exact, shadow), Tolerance::absolute(1.0 - kMinimumSsim)));
  }
  return results;
}

}  // namespace pn
