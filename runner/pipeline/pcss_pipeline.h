// The six steps of Fast PCSS (SPEC §4.7) and the baselines of SPEC §4.8 as
// one sequence of GPU passes, switched by PcssSettings: Step 1 (shadow map
// and pyramid), Step 2 (G-buffer), Step 3 (search-region map), Step 4
// (blockers, with reuse, → filter-region map), Step 5 (occluded fraction,
// with reuse → soft-shadow map), Step 6 (blur).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "device/program_variants.h"
#include "device/query_device.h"
#include "pass_runners/blur_pass.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "pass_runners/reuse_pass.h"
#include "pass_runners/shade_pass.h"
#include "pipeline/pcss_settings.h"
#include "frame/fetch_proxy.h"
#include "frame/technique.h"

namespace pn {

namespace glsl {
struct PnPcssParams;   // glsl/passes/pcss_params.h's uniform block
struct PnPoissonDisk;  // and its disk
}

struct PcssFrame {
  PcssSettings settings;
  int size = 0;  // screen side
  // Step 1's structures, the source's (TechniqueInputs) when it keeps them, else built_*: null where unused.
  const DepthPyramid* pyramid = nullptr;  // Structure::pyramid; level 0 only (the sanitized map) when nothing reads its levels
  const MinMaxMipChain* mip = nullptr;    // Structure::mip: the aligned min/max chain
  DepthPyramid built_pyramid;
  MinMaxMipChain built_mip;
  SummedAreaTable depth_sums;  // Structure::mip: summed-area table of depth (Step 4's clipped sums)
  using Texture = std::unique_ptr<DeviceTexture>;
  Texture receiver_depth;   // R32F light depth of each pixel's receiver, +Inf where it sees no surface
  Texture search_map;       // (d, x, y, s), s < 0: lit
  Texture search_keys;      // what reuse compares (pnEntryLinkKey) when it is not search_map itself (search_reuse_keys)
  Texture search_parents;   // reuse codes (k = search_tile), when reuse is on
  Texture blocker_results;  // (occluders, depth sum, texels, work) per computed pixel
  Texture filter_map;       // (d, x, y, s)
  Texture blocker_mean;     // R32F, 0 where lit
  Texture filter_keys;      // likewise
  Texture filter_parents;
  Texture occlusion_results;
  Texture visibility;       // Step 5: 1 - occluded fraction (the one call's result)
  std::optional<OneCall> one_call;  // set: the frame ran as one pass (one_call(settings), not staged), not the steps above
  Texture work;             // one call, when recorded: (visibility, Step 4's work, Step 5's work, flags)
  Texture fetches;          // one call, when recorded: the call's texel fetches per pixel
  Texture blurred;          // Step 6, when on: depth-aware over receiver_depth (blur_params.depth_aware)
  std::vector<std::pair<std::string, double>> stages;  // GPU ms, in order

  bool own_keys = true;        // false: the entries are their own reuse keys (exact regions), or reuse is off

  const DeviceTexture& soft_shadow() const { return settings.blur ? *blurred : *visibility; }
  // soft_shadow(), moved out of the frame.
  Texture take_soft_shadow() { return std::move(settings.blur ? blurred : visibility); }
  const DeviceTexture& search_reuse_keys() const { return own_keys ? *search_keys : *search_map; }
  const DeviceTexture& filter_reuse_keys() const { return own_keys ? *filter_keys : *filter_map; }
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
  // Texel fetches (fetch_proxy.h): the one call's own count; staged, Steps 4 and 5's work (a node,
  // texel or sample each: one fetch), Step 3 not counted.
  FetchProxy fetches;
};

class PcssPipeline {
 public:
  // Compiles the passes on `device` (a GL context, a Vulkan device) from `tree`.
  PcssPipeline(const QueryDevice& device, const SourceTree& tree);
  ~PcssPipeline();

  // One frame of `settings` over `inputs`; timestamps between the stages.
  // Settings with a one call (one_call()) run as an engine runs them: the
  // structure it reads, then one compute pass calling it per pixel; the others
  // run the staged passes. `record_work`: keep the one call's per-pixel work
  // for stats() (an engine's pass writes the visibility only).
  // Throws Error for invalid settings or inputs.
  PcssFrame run(const TechniqueInputs& inputs, const PcssSettings& settings, bool record_work = true) const;

  // The one call of `settings` (which must have one, staged or not) in a
  // fragment shader: a full-screen triangle over a screen-size target of
  // `channels` (4: each fragment's (visibility, Step 4's work, Step 5's work,
  // flags), what the compute pass's work image holds; 1: the visibility).
  // For the fragment-stage checks.
  std::unique_ptr<DeviceTexture> run_fragment(const TechniqueInputs& inputs, const PcssSettings& settings,
                                              int channels = 4) const;

  PcssStats stats(const PcssFrame& frame) const;

 private:
  using Block = glsl::PnPcssParams;
  using Texture = std::unique_ptr<DeviceTexture>;
  Texture float_texture(int size, int channels) const;
  Texture cleared_texture(int size, int channels) const;
  void estimate(const PcssFrame& frame, Block block, const DeviceTexture& entries, const DeviceTexture* parents,
                int tile, Estimator estimator, int samples, bool wants_depth_sums, const DeviceTexture& result) const;
  Texture link(const DeviceTexture& entries, int size, int tile, const PcssSettings& settings) const;
  // Steps 4 and 5's first half: links of `keys` (tile > 0) into `parents`, then the estimate of
  // every computing pixel's region of `entries` into `results`; two stages of `clock`, named `stages`.
  struct StageNames {
    const char* link;
    const char* estimate;
  };
  void reuse_and_estimate(PcssFrame& frame, const Block& block, StageTimes& clock, StageNames stages,
                          const DeviceTexture& keys, const DeviceTexture& entries, int tile, Estimator estimator,
                          int samples, bool wants_depth_sums, Texture& parents, Texture& results) const;
  // Step 1's structure: the pyramid's levels, or the mip chain and the depth sums, as `settings` reads them.
  // The source's structures (inputs.pyramid, inputs.mip) are used as they are when they fit.
  void build_structure(PcssFrame& frame, const TechniqueInputs& inputs, int map_size) const;
  // What the estimators read (the structures, the table, `entries` and `parents`), into `resources`.
  void add_structures(PassResources& resources, const PcssFrame& frame) const;
  // The one-call path's structure and resources (the compute and the fragment pass alike); `block`
  // and `disks` must outlive the dispatch.
  void prepare_one_call(PcssFrame& frame, OneCall call, const TechniqueInputs& inputs, Block& block,
                        PassResources& resources) const;
  PcssFrame run_one_call(PcssFrame frame, const TechniqueInputs& inputs, bool record_work) const;
  PcssFrame begin_frame(const TechniqueInputs& inputs, const PcssSettings& settings) const;
  // The disk of `samples` points: the blocker or PCF default, else one made on first use and kept.
  const glsl::PnPoissonDisk& disk(int samples) const;
  // Their second half's inputs into `resources`: `entries`, parents (tile > 0), results, and the
  // uniform block (`block`, with the tile set).
  void add_representatives(PassResources& resources, Block& block, const DeviceTexture& entries, int tile,
                           const Texture& parents, const DeviceTexture& results) const;

  const QueryDevice* device_;
  SourceTree tree_;
  DepthPyramidBuilder pyramid_;
  MinMaxMipBuilder mip_;
  SummedAreaPass depth_sums_;
  ReusePass reuse_;
  BlurPass blur_;
  ProgramVariants search_, traverse_, filter_;  // compiled per switch setting (pcss_params.glsl's PN_PCSS_*)
  ShadePass one_call_;                          // pcss_one_call.comp / .frag, per PN_PCSS_ONE_CALL
  ProgramVariants scan_, poisson_, compact_, shade_;
  Texture sample_table_, no_parents_;
  Texture no_pyramid_, no_mip_, no_depth_sums_;  // bound where a frame has no such structure
  std::unique_ptr<glsl::PnPoissonDisk> blocker_disk_, filter_disk_;
  mutable std::map<int, std::unique_ptr<glsl::PnPoissonDisk>> other_disks_;  // disk(): the other counts asked for
};

}  // namespace pn
