#include "pipeline/pcss_pipeline.h"

#include <cmath>
#include <cstdint>

#include "gl/query_device_gl.h"
#include "gl/gpu_timer.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "passes/traversal_pass.h"
#include "modules/depth_pyramid.h"
#include "modules/fast_pcss.h"
#include "sampling/poisson_disk.h"
#include "sampling/sample_table.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/pcss_params.h"
PN_STD140_SIZE(PnPcssParams, 128);
PN_STD140_OFFSET(PnPcssParams, receiverPlaneTan, 112);
PN_STD140_OFFSET(PnPcssParams, grid, 116);
PN_STD140_OFFSET(PnPcssParams, blockerLeafMode, 108);
PN_STD140_SIZE(PnPoissonFilterDisk, 16 * PN_POISSON_MAX_SAMPLES);
PN_STD140_OFFSET(PnPcssParams, lightTexelWorld, 20);
PN_STD140_OFFSET(PnPcssParams, depthSums, 88);
PN_STD140_OFFSET(PnPcssParams, refineIterations, 32);
PN_STD140_OFFSET(PnPcssParams, sigma3, 80);
PN_STD140_SIZE(PnPoissonDisk, 16 * PN_POISSON_MAX_SAMPLES);
PN_STD140_OFFSET(PnPoissonDisk, points[1], 16);
}  // namespace pn::glsl

namespace pn {

using PcssBlock = glsl::PnPcssParams;

namespace {

constexpr std::uint32_t kBlockerDiskSeed = 0x5eed0036u;
constexpr std::uint32_t kFilterDiskSeed = 0x5eed0064u;
constexpr int kScanBandRows = 128;  // pcss_scan.comp: 128 × ceil(8192 / 16) < 65535 loop iterations

PcssBlock make_block(const LightModel& light, const PcssSettings& s) {
  PcssBlock b{};
  set_light_fields(b, light);
  b.bias = s.bias;
  b.filterScale = s.filter_scale;
  b.refineIterations = s.refine_iterations;
  b.regionMode = static_cast<std::int32_t>(s.region);
  b.leafSide = s.leaf_side;
  b.leafDivisor = s.leaf_divisor;
  b.grid = s.grid;
  b.leafMode = static_cast<std::int32_t>(s.leaf_mode);
  b.nodeBudget = s.node_budget;
  b.sigma1 = s.sigma1;
  b.sigma2 = s.sigma2;
  b.sigma3 = s.sigma3;
  b.structure = static_cast<std::int32_t>(s.structure);
  b.depthSums = static_cast<std::int32_t>(s.depth_sums);  // Step 4's; estimate() sets each dispatch's
  b.blockerSamples = s.blocker_samples;
  b.filterSamples = s.filter_samples;
  b.blockerLeafMode = s.blocker_leaf_mode ? static_cast<std::int32_t>(*s.blocker_leaf_mode) : kFastPcssSameLeafMode;
  b.receiverPlaneTan = s.receiver_plane_tan;
  return b;
}

GlObject upload_disk(const Context& context, int count, std::uint32_t seed) {
  glsl::PnPoissonDisk block{};
  const PoissonDisk disk = poisson_disk(count, seed);
  for (size_t i = 0; i < disk.points.size() && i < PN_POISSON_MAX_SAMPLES; ++i)
    block.points[i] = {static_cast<float>(disk.points[i].x), static_cast<float>(disk.points[i].y)};
  return make_buffer(context, sizeof block, &block);
}

FloatTexture cleared_texture(const Context& context, int size, int channels) {
  FloatTexture t = make_float_texture(context, size, size, channels);
  const float zero[4] = {0, 0, 0, 0};
  clear_float_texture(context, t, zero);
  return t;
}

bool uses_structure_levels(const PcssSettings& s) {
  return s.refine_iterations > 0 || s.blockers == Estimator::traversal || s.occlusion == Estimator::traversal;
}

// The scan and Poisson estimators read the sanitized map (the pyramid's level 0).
bool uses_sanitized_map(const PcssSettings& s) {
  return s.structure == Structure::pyramid || s.blockers != Estimator::traversal || s.occlusion != Estimator::traversal;
}

Define switch_define(const char* name, int value) { return {name, std::to_string(value)}; }

// pcss_params.glsl's compile-time switches from the block a dispatch runs with.
std::vector<Define> search_defines(const PcssBlock& b) {
  return {switch_define("PN_PCSS_STRUCTURE", b.structure), switch_define("PN_PCSS_REGION_MODE", b.regionMode),
          {"PN_PCSS_WRITE_KEYS", b.writeKeys != 0 ? "true" : "false"}};
}
std::vector<Define> filter_defines(const PcssBlock& b) {
  return {switch_define("PN_PCSS_REGION_MODE", b.regionMode), {"PN_PCSS_WRITE_KEYS", b.writeKeys != 0 ? "true" : "false"}};
}
std::vector<Define> traverse_defines(const PcssBlock& b) {
  return {switch_define("PN_PCSS_STRUCTURE", b.structure), switch_define("PN_PCSS_REGION_MODE", b.regionMode),
          switch_define("PN_PCSS_LEAF_MODE", b.leafMode), switch_define("PN_PCSS_DEPTH_SUMS", b.depthSums)};
}

}  // namespace

double PcssStats::representative_fraction() const {
  const long regions = searched + filtered;
  return regions > 0 ? static_cast<double>(search_computed + filter_computed) / static_cast<double>(regions) : 0.0;
}

double PcssStats::work_per_receiver() const {
  return receivers > 0 ? (blocker_work + occlusion_work) / static_cast<double>(receivers) : 0.0;
}

PcssPipeline::PcssPipeline(const Context& context, const SourceTree& tree)
    : context_(&context),
      pyramid_(context, tree),
      mip_(context, tree),
      depth_sums_(context, tree),
      reuse_(context, tree),
      blur_(context, tree),
      search_(context, tree, "passes/pcss_search.comp"),
      traverse_(context, tree, "passes/pcss_traverse.comp"),
      filter_(context, tree, "passes/pcss_filter.comp"),
      one_call_(context, tree, "passes/pcss_one_call", PN_PCSS_VISIBILITY_IMAGE),
      scan_(compile_pass(context, tree, "passes/pcss_scan.comp")),
      poisson_(compile_pass(context, tree, "passes/pcss_poisson.comp")),
      compact_(compile_pass(context, tree, "passes/pcss_compact.comp")),
      shade_(compile_pass(context, tree, "passes/pcss_shade.comp")),
      sample_table_(upload_float_texture(context, generate_sample_table(kSampleTableSeed).image())),
      blocker_disk_(upload_disk(context, PcssSettings{}.blocker_samples, kBlockerDiskSeed)),
      filter_disk_(upload_disk(context, PcssSettings{}.filter_samples, kFilterDiskSeed)),
      no_parents_(cleared_texture(context, 1, 1)),
      no_pyramid_(make_placeholder_texture(context, GL_TEXTURE_2D_ARRAY, GL_RGBA32F)),
      no_mip_(make_placeholder_texture(context, GL_TEXTURE_2D, GL_RGBA32F)),
      no_depth_sums_(make_placeholder_texture(context, GL_TEXTURE_2D, GL_RGBA32UI)) {}

void PcssPipeline::build_structure(PcssFrame& frame, const TechniqueInputs& inputs, int n) const {
  const PcssSettings& s = frame.settings;
  const GlObject& shadow_map = *inputs.shadow_map;
  const bool levels = uses_structure_levels(s);
  if (uses_sanitized_map(s)) {
    const int max_level = s.structure == Structure::pyramid && levels ? 31 : 0;
    const DepthPyramid* kept = inputs.pyramid;  // the source's, kept up to date, when it has the levels read here
    if (kept && kept->map_size == n && kept->levels >= pyramid_level_count(n, max_level)) {
      frame.pyramid = kept;
    } else {
      frame.built_pyramid = pyramid_.build(GlDeviceTexture(shadow_map), n, n, max_level);
      frame.pyramid = &frame.built_pyramid;
    }
  }
  if (s.structure == Structure::mip && levels) {
    if (inputs.mip && inputs.mip->map_size == n) {
      frame.mip = inputs.mip;
    } else {
      frame.built_mip = mip_.build(GlDeviceTexture(shadow_map), n);
      frame.mip = &frame.built_mip;
    }
    if (s.blockers == Estimator::traversal && s.depth_sums == DepthSums::table)
      frame.depth_sums = depth_sums_.build(GlDeviceTexture(shadow_map), n, n);
  }
}

GlObject PcssPipeline::link(const GlObject& entries, int size, int tile, const PcssSettings& s) const {
  ReuseParams params;
  params.sigma1 = s.sigma1;
  params.sigma2 = s.sigma2;
  params.sigma3 = s.sigma3;
  params.tile = tile;
  return take_float_texture(reuse_.link(GlDeviceTexture(entries), size, size, params));
}

void PcssPipeline::estimate(const PcssFrame& frame, PcssBlock block, const GlObject& entries, const GlObject* parents,
                            int tile, Estimator estimator, int samples, bool wants_depth_sums,
                            const GlObject& result) const {
  const int size = frame.size;
  block.reuseTile = parents ? tile : 0;
  block.sampleCount = samples;
  block.depthSums = static_cast<std::int32_t>(wants_depth_sums ? frame.settings.depth_sums : DepthSums::none);
  if (wants_depth_sums && frame.settings.blocker_leaf_mode)  // Step 4: the blocker mean's own leaves
    block.leafMode = static_cast<std::int32_t>(*frame.settings.blocker_leaf_mode);
  // What every estimator reads; each dispatch below binds it in its own scope.
  const auto bind_inputs = [&](PassBindings& bind) {
    bind.texture(PN_PCSS_PYRAMID_BINDING, frame.pyramid ? gl_texture(*frame.pyramid->texture) : no_pyramid_);
    bind.texture(PN_PCSS_MIP_BINDING, frame.mip ? gl_texture(*frame.mip->texture) : no_mip_);
    bind.texture(PN_PCSS_DEPTH_SUMS_BINDING, frame.depth_sums.texture ? gl_texture(*frame.depth_sums.texture) : no_depth_sums_);
    bind.texture(PN_PCSS_SAMPLE_TABLE_BINDING, sample_table_);
    bind.texture(PN_PCSS_ENTRIES_BINDING, entries);
    bind.texture(PN_PCSS_PARENTS_BINDING, parents ? *parents : no_parents_);
    bind.texture(PN_PCSS_DEPTH_MAP_BINDING, frame.pyramid ? gl_texture(*frame.pyramid->level0) : no_mip_);  // sampler2D of the sanitized map
  };

  if (estimator == Estimator::scan) {
    // Bands of rows, ping-pong between `result` and a partner so the last band lands in `result`.
    GlObject partner = cleared_texture(*context_, size, 4);
    const int bands = (frame.pyramid->map_size + kScanBandRows - 1) / kScanBandRows;
    const GlObject* target[2] = {&result, &partner};
    const int first = (bands - 1) % 2;
    for (int band = 0; band < bands; ++band) {
      block.bandStart = band * kScanBandRows;
      block.bandRows = kScanBandRows;
      PassBindings bind(*context_);
      bind_inputs(bind);
      bind.uniform(block);
      bind.texture(PN_PCSS_RESULTS_BINDING, *target[(first + band + 1) % 2]);  // the previous band
      bind.image(PN_PCSS_RESULT_IMAGE, *target[(first + band) % 2], GL_WRITE_ONLY, GL_RGBA32F);
      scan_.dispatch(size, size);
    }
    return;
  }

  const ComputeProgram& program = estimator == Estimator::poisson ? poisson_ : traverse_.get(traverse_defines(block));
  // The list holds the pixels that must compute — not lit, and representatives
  // when reuse is on — so lit pixels are skipped with or without reuse.
  const bool list = frame.settings.skip == WorkSkip::list;
  block.workMode = list ? PN_WORK_LIST : parents ? PN_WORK_BRANCH : PN_WORK_ALL;
  PassBindings bind(*context_);
  bind_inputs(bind);
  bind.uniform(block);
  if (estimator == Estimator::poisson) bind.uniform_buffer(PN_PCSS_POISSON_DISK_BINDING, disk(samples));
  // The work list: its header (groups x, y, z; count), and room for every pixel only when listing.
  const std::size_t header = 4 * sizeof(std::uint32_t);
  const std::size_t room = list ? static_cast<std::size_t>(size) * size * 2 * sizeof(std::uint32_t) : 0;
  const GlObject work = make_buffer(*context_, header + room, nullptr, GL_DYNAMIC_COPY);
  const std::uint32_t start[4] = {0, 1, 1, 0};
  write_buffer(*context_, work, 0, header, start);
  bind.storage_buffer(PN_PCSS_WORK_LIST_BINDING, work);
  bind.image(PN_PCSS_RESULT_IMAGE, result, GL_WRITE_ONLY, GL_RGBA32F);
  if (list) {
    compact_.dispatch(size, size);
    program.dispatch_indirect(work);
  } else {
    program.dispatch(size * size, 1);
  }
}

const GlObject& PcssPipeline::disk(int samples) const {
  if (samples == PN_POISSON_BLOCKER_SAMPLES) return blocker_disk_;
  if (samples == PN_POISSON_PCF_SAMPLES) return filter_disk_;
  // A count other than the defaults gets its own disk, made once (Bridson's algorithm on the CPU and
  // an upload: not a per-frame cost an engine pays, so not inside a timed frame after the first).
  auto found = other_disks_.find(samples);
  if (found == other_disks_.end()) found = other_disks_.emplace(samples, upload_disk(*context_, samples, kFilterDiskSeed)).first;
  return found->second;
}

void PcssPipeline::reuse_and_estimate(PcssFrame& frame, const PcssBlock& block, StageClock& clock,
                                      StageNames stages, const GlObject& keys, const GlObject& entries, int tile,
                                      Estimator estimator, int samples, bool wants_depth_sums, GlObject& parents,
                                      GlObject& results) const {
  if (tile > 0) parents = link(keys, frame.size, tile, frame.settings);
  clock.stage(stages.link);
  results = cleared_texture(*context_, frame.size, 4);
  estimate(frame, block, entries, tile > 0 ? &parents : nullptr, tile, estimator, samples, wants_depth_sums, results);
  clock.stage(stages.estimate);
}

void PcssPipeline::bind_representatives(PassBindings& bind, PcssBlock block, const GlObject& entries, int tile,
                                        const GlObject& parents, const GlObject& results) const {
  block.reuseTile = tile;
  bind.uniform(block);
  bind.texture(PN_PCSS_ENTRIES_BINDING, entries);
  bind.texture(PN_PCSS_PARENTS_BINDING, tile > 0 ? parents : no_parents_);
  bind.texture(PN_PCSS_RESULTS_BINDING, results);
}

PcssFrame PcssPipeline::begin_frame(const TechniqueInputs& inputs, const PcssSettings& settings) const {
  settings.validate();
  if (!inputs.shadow_map || !inputs.gbuffer || inputs.screen_size < 1)
    throw Error("PCSS frame '" + settings.name + "': expected a shadow map, a G-buffer and a screen size >= 1");
  PcssFrame frame;
  frame.settings = settings;
  frame.size = inputs.screen_size;
  if (!settings.staged) frame.one_call = one_call(settings);
  return frame;
}

void PcssPipeline::prepare_one_call(PcssFrame& frame, OneCall call, const TechniqueInputs& inputs,
                                    PassBindings& bind) const {
  const PcssSettings& s = frame.settings;
  // What the call reads: the mip chain (and the sums table when asked) for pnFastPcss, the pyramid for
  // pnHqepcss; and the map itself (the calls skip non-finite texels as the sanitized copy's +Inf is skipped).
  if (call == OneCall::fast || call == OneCall::hqepcss)
    build_structure(frame, inputs, inputs.light.map_size);
  bind.uniform(make_block(inputs.light, s));
  bind.texture(PN_PCSS_SHADE_GBUFFER_BINDING, *inputs.gbuffer);
  bind.texture(PN_PCSS_MIP_BINDING, frame.mip ? gl_texture(*frame.mip->texture) : no_mip_);
  bind.texture(PN_PCSS_PYRAMID_BINDING, frame.pyramid ? gl_texture(*frame.pyramid->texture) : no_pyramid_);
  bind.texture(PN_PCSS_SAMPLE_TABLE_BINDING, sample_table_);
  bind.texture(PN_PCSS_DEPTH_SUMS_BINDING, frame.depth_sums.texture ? gl_texture(*frame.depth_sums.texture) : no_depth_sums_);
  bind.texture(PN_PCSS_DEPTH_MAP_BINDING, *inputs.shadow_map);
  // Only the Poisson call reads its disks; the others bind the defaults (a Vogel count may exceed the block's).
  const bool poisson = call == OneCall::poisson;
  bind.uniform_buffer(PN_PCSS_POISSON_DISK_BINDING, poisson ? disk(s.blocker_samples) : blocker_disk_);
  bind.uniform_buffer(PN_PCSS_POISSON_FILTER_DISK_BINDING, poisson ? disk(s.filter_samples) : filter_disk_);
}

static_assert(static_cast<int>(OneCall::fast) == PN_ONE_CALL_FAST && static_cast<int>(OneCall::poisson) == PN_ONE_CALL_POISSON &&
                  static_cast<int>(OneCall::exact) == PN_ONE_CALL_EXACT &&
                  static_cast<int>(OneCall::hqepcss) == PN_ONE_CALL_HQEPCSS &&
                  static_cast<int>(OneCall::vogel) == PN_ONE_CALL_VOGEL,
              "OneCall is pcss_params.h's PN_ONE_CALL_*");

static std::vector<Define> one_call_defines(OneCall call, bool record_work) {
  return {{"PN_PCSS_ONE_CALL", std::to_string(static_cast<int>(call))},
          {"PN_PCSS_WRITE_WORK", record_work ? "true" : "false"}};
}

PcssFrame PcssPipeline::run_one_call(PcssFrame frame, const TechniqueInputs& inputs, bool record_work) const {
  const int size = frame.size;
  StageClock clock(*context_);
  clock.start();
  PassBindings bind(*context_);
  const OneCall call = *frame.one_call;
  prepare_one_call(frame, call, inputs, bind);
  clock.stage(call == OneCall::hqepcss                ? "pyramid"
              : call != OneCall::fast                 ? "no structure"
              : frame.depth_sums.texture    ? "mip chain + sums"
                                                      : "mip chain");
  frame.work = record_work ? make_float_texture(*context_, size, size, 4) : cleared_texture(*context_, 1, 4);
  bind.image(PN_PCSS_WORK_IMAGE, frame.work, GL_WRITE_ONLY, GL_RGBA32F);
  frame.fetches = record_work ? make_float_texture(*context_, size, size, 1) : cleared_texture(*context_, 1, 1);
  bind.image(PN_PCSS_FETCH_IMAGE, frame.fetches, GL_WRITE_ONLY, GL_R32F);
  frame.visibility = one_call_.run(ShadeStage::compute, one_call_defines(call, record_work), size, bind);
  clock.stage("one call");
  frame.stages = clock.read();
  context_->throw_if_gl_error("PCSS frame '" + frame.settings.name + "'");
  return frame;
}

FloatTexture PcssPipeline::run_fragment(const TechniqueInputs& inputs, const PcssSettings& settings,
                                        int channels) const {
  PcssFrame frame = begin_frame(inputs, settings);
  const std::optional<OneCall> call = one_call(settings);
  if (!call)
    throw Error("PCSS frame '" + settings.name + "': no one call to run in a fragment shader (reuse and blur need "
                "neighbours; the other combinations are staged ablations)");
  PassBindings bind(*context_);
  prepare_one_call(frame, *call, inputs, bind);
  FloatTexture out = one_call_.run(ShadeStage::fragment, one_call_defines(*call, true), frame.size, bind, channels);
  context_->throw_if_gl_error("PCSS frame '" + settings.name + "' in a fragment shader");
  return out;
}

PcssFrame PcssPipeline::run(const TechniqueInputs& inputs, const PcssSettings& settings, bool record_work) const {
  PcssFrame frame = begin_frame(inputs, settings);
  if (frame.one_call) return run_one_call(std::move(frame), inputs, record_work);
  const int size = frame.size;
  const int n = inputs.light.map_size;
  StageClock clock(*context_);
  clock.start();

  // Step 1's structure: what Steps 3-5 read.
  build_structure(frame, inputs, n);
  clock.stage(settings.structure == Structure::pyramid ? "pyramid"
              : frame.depth_sums.texture ? "mip chain + sums"
                                                   : "mip chain");

  // Step 3.
  const PcssBlock block = make_block(inputs.light, settings);
  frame.search_map = make_float_texture(*context_, size, size, 4);
  // Reuse keys of their own only when reuse is on and they differ from the entries (pnEntryLinkKey).
  frame.own_keys = settings.region != RegionMode::exact;
  const bool own_search_keys = frame.own_keys && settings.search_tile > 0;
  const bool own_filter_keys = frame.own_keys && settings.filter_tile > 0;
  frame.search_keys = own_search_keys ? make_float_texture(*context_, size, size, 4) : cleared_texture(*context_, 1, 4);
  frame.receiver_depth = make_float_texture(*context_, size, size, 1);
  {
    PassBindings bind(*context_);
    PcssBlock search_block = block;
    search_block.writeKeys = own_search_keys ? 1 : 0;
    bind.uniform(search_block);
    bind.texture(PN_PCSS_PYRAMID_BINDING, frame.pyramid ? gl_texture(*frame.pyramid->texture) : no_pyramid_);
    bind.texture(PN_PCSS_MIP_BINDING, frame.mip ? gl_texture(*frame.mip->texture) : no_mip_);
    bind.texture(PN_PCSS_GBUFFER_BINDING, *inputs.gbuffer);
    bind.image(PN_PCSS_SEARCH_MAP_IMAGE, frame.search_map, GL_WRITE_ONLY, GL_RGBA32F);
    bind.image(PN_PCSS_SEARCH_KEYS_IMAGE, frame.search_keys, GL_WRITE_ONLY, GL_RGBA32F);
    bind.image(PN_PCSS_RECEIVER_DEPTH_IMAGE, frame.receiver_depth, GL_WRITE_ONLY, GL_R32F);
    search_.get(search_defines(search_block)).dispatch(size, size);
  }
  clock.stage("3 search region");

  // Step 4: blockers of the representatives, then every pixel's filter region.
  reuse_and_estimate(frame, block, clock, {"4 reuse link", "4 blockers"},
                     frame.search_reuse_keys(), frame.search_map, settings.search_tile,
                     settings.blockers, settings.blocker_samples, true, frame.search_parents, frame.blocker_results);
  frame.filter_map = make_float_texture(*context_, size, size, 4);
  frame.blocker_mean = make_float_texture(*context_, size, size, 1);
  frame.filter_keys = own_filter_keys ? make_float_texture(*context_, size, size, 4) : cleared_texture(*context_, 1, 4);
  {
    PassBindings bind(*context_);
    PcssBlock filter_block = block;
    filter_block.writeKeys = own_filter_keys ? 1 : 0;
    bind_representatives(bind, filter_block, frame.search_map, settings.search_tile, frame.search_parents,
                         frame.blocker_results);
    bind.image(PN_PCSS_FILTER_MAP_IMAGE, frame.filter_map, GL_WRITE_ONLY, GL_RGBA32F);
    bind.image(PN_PCSS_BLOCKER_MEAN_IMAGE, frame.blocker_mean, GL_WRITE_ONLY, GL_R32F);
    bind.image(PN_PCSS_FILTER_KEYS_IMAGE, frame.filter_keys, GL_WRITE_ONLY, GL_RGBA32F);
    filter_.get(filter_defines(filter_block)).dispatch(size, size);
  }
  clock.stage("4 filter region");

  // Step 5: occluded fraction of the representatives, then every pixel's visibility.
  reuse_and_estimate(frame, block, clock, {"5 reuse link", "5 occlusion"},
                     frame.filter_reuse_keys(), frame.filter_map, settings.filter_tile,
                     settings.occlusion, settings.filter_samples, false, frame.filter_parents, frame.occlusion_results);
  frame.visibility = make_float_texture(*context_, size, size, 1);
  {
    PassBindings bind(*context_);
    bind_representatives(bind, block, frame.filter_map, settings.filter_tile, frame.filter_parents, frame.occlusion_results);
    bind.image(PN_PCSS_VISIBILITY_IMAGE, frame.visibility, GL_WRITE_ONLY, GL_R32F);
    shade_.dispatch(size, size);
  }
  clock.stage("5 shade");

  // Step 6.
  if (settings.blur) {
    frame.settings.blur_params.pixels_per_texel = static_cast<float>(size / static_cast<double>(n));  // adaptive radius's k
    const GlDeviceTexture visibility(frame.visibility), receiver_depth(frame.receiver_depth),
        filter_map(frame.filter_map);
    frame.blurred = take_float_texture(
        blur_.run(visibility, &receiver_depth, size, size, frame.settings.blur_params, &filter_map));
  }
  clock.stage("6 blur");
  frame.stages = clock.read();
  context_->throw_if_gl_error("PCSS frame '" + settings.name + "'");
  return frame;
}

PcssStats PcssPipeline::stats(const PcssFrame& frame) const {
  const int size = frame.size;
  if (frame.one_call) {
    if (frame.work.width != size) throw Error("PCSS frame '" + frame.settings.name + "': its work was not recorded");
    const Image work = read_float_texture(*context_, frame.work);
    PcssStats s;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int flags = static_cast<int>(work.at(x, y, 3));
        if (flags & 4) ++s.receivers;
        if (flags & 1) ++s.searched, ++s.search_computed, s.blocker_work += work.at(x, y, 1);
        if (flags & 2) ++s.filtered, ++s.filter_computed, s.occlusion_work += work.at(x, y, 2);
      }
    s.fetches = fetch_proxy(read_float_texture(*context_, frame.fetches),
                            [&](int x, int y) { return (static_cast<int>(work.at(x, y, 3)) & 4) != 0; });
    return s;
  }
  const auto read4 = [&](const GlObject& t) { return read_float_texture(*context_, t, size, size, 4); };
  const auto read1 = [&](const GlObject& t) { return read_float_texture(*context_, t, size, size, 1); };
  const Image search = read_float_texture(*context_, frame.search_map), filter = read_float_texture(*context_, frame.filter_map);
  const Image blockers = read4(frame.blocker_results), occlusion = read4(frame.occlusion_results);
  const bool search_reuse = frame.settings.search_tile > 0, filter_reuse = frame.settings.filter_tile > 0;
  const Image search_parents = search_reuse ? read1(frame.search_parents) : Image(size, size);
  const Image filter_parents = filter_reuse ? read1(frame.filter_parents) : Image(size, size);
  PcssStats s;
  Image fetches(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (search.at(x, y, 0) > 0.0f) ++s.receivers;
      if (search.at(x, y, 3) >= 0.0f) {
        ++s.searched;
        if (search_parents.at(x, y) == static_cast<float>(PN_REUSE_NONE)) {
          ++s.search_computed;
          s.blocker_work += blockers.at(x, y, 3);
          fetches.at(x, y) += blockers.at(x, y, 3);
        }
      }
      if (filter.at(x, y, 3) >= 0.0f) {
        ++s.filtered;
        if (filter_parents.at(x, y) == static_cast<float>(PN_REUSE_NONE)) {
          ++s.filter_computed;
          s.occlusion_work += occlusion.at(x, y, 3);
          fetches.at(x, y) += occlusion.at(x, y, 3);
        }
      }
    }
  s.fetches = fetch_proxy(fetches, [&](int x, int y) { return search.at(x, y, 0) > 0.0f; });
  return s;
}

}  // namespace pn
