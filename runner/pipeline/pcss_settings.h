// What a PCSS run computes: every technique of SPEC §4.8 is one PcssSettings
// over the same passes (runner/pipeline/pcss_pipeline.h), so exact PCSS,
// Poisson PCSS, HQEPCSS and Fast PCSS differ only in these switches.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "modules/blur_face.h"
#include "modules/fast_pcss_face.h"
#include "modules/pcss_regions_face.h"
#include "modules/poisson_pcss_face.h"
#include "modules/receiver_plane_face.h"
#include "modules/reuse_face.h"
#include "modules/traversal_face.h"
#include "modules/vogel_pcss_face.h"

namespace pn {

// How Steps 4 and 5 estimate a region.
enum class Estimator {
  scan,       // every texel (exact PCSS)
  traversal,  // quadtree over the pyramid (traversal.glsl)
  poisson,    // fixed Poisson-disk samples (Poisson PCSS)
  vogel,      // a Vogel disk rotated per pixel (vogel_pcss.glsl): its one call only
};

// How the GPU skips the pixels that need not compute in Steps 4 and 5 — lit
// ones, and the reuse scheme's non-representatives (pcss_work.glsl). The
// brute-force scan of exact PCSS always runs over every pixel.
enum class WorkSkip {
  branch,  // every pixel dispatched; those with nothing to do return at once
  list,    // the pixels that compute compacted into a list, dispatched indirectly
};

// Step 6 cuts the blur where two receivers' light depths differ by more than
// this fraction (blur.glsl's depth-aware variant): across the G-buffer's depth
// edges, and between a surface and a pixel that sees none (+Inf).
inline constexpr double kBlurDepthTolerance = 0.05;

// The defaults of PcssSettings are the paper's (fast_paper_pcss); fast_pcss()
// is Fast PCSS as this project ships it, chosen by measurement.
struct PcssSettings {
  std::string name;
  float bias = 0.02f;          // world units of light depth: d occludes when d < dP - bias
  float filter_scale = 1.0f;   // c: filter side = c · penumbra (Step 4)
  int refine_iterations = 8;   // Step 3 refinement with the pyramid; 0 = off (PCSS's width)
  RegionMode region = RegionMode::window;
  Structure structure = Structure::pyramid;
  DepthSums depth_sums = DepthSums::table;  // Step 4 over the mip chain: its wholly occluding nodes' depth sums
  Estimator blockers = Estimator::traversal;  // Step 4
  Estimator occlusion = Estimator::traversal; // Step 5
  int leaf_side = 8;           // traversal leaves; 1 = exact (sampled leaves off)
  int leaf_divisor = 0;        // > 0: leaves at least the region's side / leaf_divisor (pcss_traverse.comp); 0 = off
  // > 0: Steps 4 and 5 over the mip chain count a grid of about grid² aligned nodes instead of
  // traversing (traversal.glsl, pnGridRegionMip): bounded work; 0 = off. 1..PN_GRID_MAX_CELLS.
  int grid = 0;
  LeafMode leaf_mode = LeafMode::sampled;
  std::optional<LeafMode> blocker_leaf_mode;  // Step 4's leaves when set (the blocker mean), else leaf_mode
  int node_budget = kFastPcssNodeBudget;  // per pixel (traversal.glsl): 2^26, unbounded in effect
  int search_tile = 4;         // reuse k for Step 4; 0 = no reuse
  int filter_tile = 2;         // reuse k for Step 5; 0 = no reuse
  float sigma1 = 0.0f, sigma2 = 0.1f, sigma3 = 0.1f;  // Eq. 7 (§5.2 defaults)
  WorkSkip skip = WorkSkip::list;
  // Poisson PCSS: 36 / 64, 1..kPoissonMaxSamples (64); Vogel PCSS: 1..kVogelMaxSamples (128).
  int blocker_samples = kPoissonBlockerSamples;
  int filter_samples = kPoissonPcfSamples;
  bool blur = true;            // Step 6
  // Radius 3 (§5.3), depth-aware; the adaptive radius (blur.glsl: at most half
  // the pixel's penumbra, 0 on lit pixels and contact shadows) off for now.
  // pixels_per_texel is the frame's (screen size / map size), set by Step 6.
  BlurParams blur_params{PN_BLUR_RADIUS, PN_BLUR_SIGMA, true, kBlurDepthTolerance, false};
  // Run through the staged passes (a pass a step, per-stage times) even where
  // the settings are a one-call technique (one_call below). Exact PCSS and
  // HQEPCSS default to it: their brute-force PCF in one call runs past
  // llvmpipe's cap of 65535 loop iterations an invocation on regions wider
  // than ~1000 texels, which the staged scan's bands of rows stay under.
  bool staged = false;
  // > 0: the receiver-plane depth bias (receiver_plane.glsl) from the G-buffer's neighbours, its slope
  // clamped to this tangent; 0: off. The one calls of fast, exact and vogel (validate).
  float receiver_plane_tan = 0.0f;
  // Issue 51 (docs/area-regions.md): `edges=area` (true) both regions as squares with
  // area-weighted edges, `edges=texel` (false) the integer squares; unset, the modules' default
  // (PN_AREA_EDGES 1, pcss_regions.glsl) where the technique has such squares (exact PCSS,
  // HQEPCSS, Fast PCSS over exact regions: has_area_squares) and the integer form elsewhere.
  // Every pass is compiled with PN_AREA_EDGES set to area_edges() (pcss_pipeline.cpp).
  std::optional<bool> edges;
  bool area_edges() const;

  // Throws Error naming the setting and its accepted range.
  void validate() const;
};

// The one call an engine makes that computes `s` in one pass, or none: reuse
// and blur need neighbours, and the other combinations of estimators and
// structures are ablations no engine ships. (Whether a frame runs it or the
// staged passes is `staged`'s choice.)
enum class OneCall {
  fast,     // pnFastPcss (fast_pcss.glsl)
  poisson,  // pnPoissonPcss (poisson_pcss.glsl)
  exact,    // pnExactPcss (exact_pcss.glsl)
  hqepcss,  // pnHqepcss (hqepcss.glsl)
  vogel,    // pnVogelPcss (vogel_pcss.glsl)
};
std::optional<OneCall> one_call(const PcssSettings& s);
// Whether `s` reads squares that can weigh their edges (PN_AREA_EDGES): exact PCSS, HQEPCSS and Fast
// PCSS over exact regions, one call or staged; the others have no squares (docs/area-regions.md).
bool has_area_squares(const PcssSettings& s);
// Whether `s` is its one call's shipped settings — everything the call reads but the bias and the
// receiver plane equal to its technique's (fast_pcss(), poisson_pcss(), vogel_pcss(), hqepcss():
// the module's pnXDefaults) — so that the runner's pass compiles the call as an engine does, the
// defaults as constants (PN_PCSS_ENGINE_FORM, pcss_one_call.glsl). Fast PCSS's work budget may
// differ (leaf_divisor, and a sampling leaf_mode): the pass then defines PN_FAST_PCSS_LEAF_DIVISOR
// and _MODE as an engine that sets its budget does (fast_pcss.h). Exact PCSS's call has plain
// parameters, no defaults: never.
bool shipped_call_settings(const PcssSettings& s);

PcssSettings exact_pcss();    // brute force over the whole search and filter regions
PcssSettings poisson_pcss();  // 36 blocker / 64 PCF Poisson-disk samples
PcssSettings vogel_pcss();    // 16 blocker / 32 PCF Vogel-disk samples, rotated per pixel
PcssSettings hqepcss();       // refined search, min-estimated leaves for blockers, brute-force PCF
PcssSettings fast_paper_pcss();  // seed 000 with the paper's settings (§5: windows, leaf 8, reuse 4/2, blur radius 3)
PcssSettings fast_pcss();        // Fast PCSS's defaults, chosen with the bench (docs/benchmarks.md)

// What the `fast` technique runs: fast_pcss() with the receiver-plane depth bias from the
// G-buffer's neighbours, slopes clamped at tan 1 (docs/modules/receiver_plane.md, "Measured, the
// one-sided plane": the city's acne under a wide sun gone, issue 42 §5; equal or better than no
// plane in MAE at 17 of the 20 frontier points at 256²). fast_pcss() keeps none: the staged passes take
// no plane, and the ablations are one switch from it.
PcssSettings shipped_fast_pcss();
inline constexpr float kShippedReceiverPlaneTan = 1.0f;

// Fast PCSS with every improvement off, which must equal exact PCSS (the wiring check).
PcssSettings fast_pcss_all_off();

// The override keys of every PCSS technique, and setting one: Throws Error
// naming the technique (s.name), the key and what it expects. The caller
// validates once all keys are set.
const std::vector<std::string>& pcss_setting_keys();
void set_pcss_setting(PcssSettings& s, const std::string& key, const std::string& value);

}  // namespace pn
