// The six steps of Fast PCSS (SPEC §4.7) and the baselines of SPEC §4.8 as
// one sequence of GPU passes, switched by PcssSettings: Step 1 (shadow map
// and pyramid), Step 2 (G-buffer), Step 3 (search-region map), Step 4
// (blockers, with reuse, → filter-region map), Step 5 (occluded fraction,
// with reuse → soft-shadow map), Step 6 (blur).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "gl/gpu_timer.h"
#include "gl/compute_program.h"
#include "passes/blur_pass.h"
#include "passes/depth_pyramid_pass.h"
#include "passes/gbuffer_pass.h"
#include "passes/reuse_pass.h"
#include "passes/shadow_map_pass.h"
#include "pipeline/pcss_settings.h"
#include "scene/scene.h"

namespace pn {

struct PcssBlock;  // glsl/passes/pcss_params.glsl's uniform block

// Steps 1 and 2 without the pyramid: the same for every technique.
struct PcssInputs {
  LightModel light;
  int screen_size = 0;
  GlObject shadow_map;  // N×N R32F linear light depth, +Inf where empty
  GlObject gbuffer;     // screen² RGBA32F (u, v in texels, light depth, valid)
};

struct PcssFrame {
  PcssSettings settings;
  int size = 0;  // screen side
  DepthPyramid pyramid;
  GlObject search_map;         // (d, x, y, s), s < 0: lit
  GlObject search_keys;        // what reuse compares (pnEntryLinkKey)
  GlObject search_parents;     // reuse codes (k = search_tile), when reuse is on
  GlObject blocker_results;    // (occluders, depth sum, texels, work) per computed pixel
  GlObject filter_map;         // (d, x, y, s)
  GlObject blocker_mean;       // R32F, 0 where lit
  GlObject filter_keys;
  GlObject filter_parents;
  GlObject occlusion_results;
  GlObject visibility;         // Step 5: 1 - occluded fraction
  GlObject blurred;            // Step 6, when on
  std::vector<std::pair<std::string, double>> stages;  // GPU ms, in order

  const GlObject& soft_shadow() const { return settings.blur ? blurred : visibility; }
  double total_ms() const;
};

// What a frame did, counted on the CPU from its maps.
struct PcssStats {
  long receivers = 0;             // pixels that see a surface
  long searched = 0;              // not lit after Step 3
  long search_computed = 0;       // of those, representatives (all without reuse)
  long filtered = 0;              // with a filter region after Step 4
  long filter_computed = 0;
  double blocker_work = 0.0;      // nodes (traversal), texels (scan) or samples (Poisson), summed
  double occlusion_work = 0.0;
  double representative_fraction() const;  // computed / regions, Steps 4 and 5 together
  double work_per_receiver() const;
};

// Repeated runs of one technique: the last frame, medians of the GPU times, its stats.
struct PcssMeasurement {
  PcssFrame frame;
  double total_ms = 0.0;
  std::vector<std::pair<std::string, double>> stage_ms;
  PcssStats stats;
};

class PcssPipeline {
 public:
  PcssPipeline(const Context& context, const SourceTree& tree);

  PcssInputs render_inputs(const Scene& scene, int screen_size) const;

  // One frame of `settings` over `inputs`; timestamps between the stages.
  // Throws Error for invalid settings.
  PcssFrame run(const PcssInputs& inputs, const PcssSettings& settings) const;

  PcssStats stats(const PcssFrame& frame) const;

  // One untimed warm-up run, then `repeats` >= 1 runs; medians of the total and of each stage.
  PcssMeasurement measure(const PcssInputs& inputs, const PcssSettings& settings, int repeats) const;

 private:
  void estimate(const PcssFrame& frame, PcssBlock block, const GlObject& entries, const GlObject* parents, int tile,
                Estimator estimator, int samples, const GlObject& result) const;
  GlObject link(const GlObject& entries, int size, int tile, const PcssSettings& settings) const;
  // Steps 4 and 5's first half: links of `keys` (tile > 0) into `parents`, then the estimate of
  // every computing pixel's region of `entries` into `results`; two stages of `clock`.
  void reuse_and_estimate(PcssFrame& frame, const PcssBlock& block, StageClock& clock, const std::string& step,
                          const GlObject& keys, const GlObject& entries, int tile, Estimator estimator, int samples,
                          GlObject& parents, GlObject& results) const;
  // Their second half's inputs: `entries`, parents (tile > 0) and results at units 2, 4, 5, and the
  // uniform block with the tile (returned: bound while it lives).
  GlObject bind_representatives(const PcssBlock& block, const GlObject& entries, int tile, const GlObject& parents,
                                const GlObject& results) const;

  const Context* context_;
  ShadowMapRenderer shadow_map_;
  GBufferRenderer gbuffer_;
  DepthPyramidBuilder pyramid_;
  ReusePass reuse_;
  BlurPass blur_;
  ComputeProgram search_, traverse_, scan_, poisson_, compact_, filter_, shade_;
  GlObject sample_table_, blocker_disk_, filter_disk_, no_parents_;
};

}  // namespace pn
