#include "pipeline/pcss_pipeline.h"

#include <cmath>
#include <cstdint>

#include "gl/std140.h"
#include "pass_runners/traversal_pass.h"
#include "modules/depth_pyramid_face.h"
#include "modules/fast_pcss_face.h"
#include "sampling/poisson_disk.h"
#include "sampling/sample_table_generator.h"
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

std::unique_ptr<glsl::PnPoissonDisk> make_disk(int count, std::uint32_t seed) {
  auto block = std::make_unique<glsl::PnPoissonDisk>();
  *block = {};
  const PoissonDisk disk = poisson_disk(count, seed);
  for (size_t i = 0; i < disk.points.size() && i < PN_POISSON_MAX_SAMPLES; ++i)
    block->points[i] = {static_cast<float>(disk.points[i].x), static_cast<float>(disk.points[i].y)};
  return block;
}

// A disk at `binding` (the blocker's or the PCF's: one layout).
QueryBlock disk_block(unsigned binding, const glsl::PnPoissonDisk& disk) { return {binding, &disk, sizeof disk}; }

bool uses_structure_levels(const PcssSettings& s) {
  return s.refine_iterations > 0 || s.blockers == Estimator::traversal || s.occlusion == Estimator::traversal;
}

// The scan and Poisson estimators read the sanitized map (the pyramid's level 0).
bool uses_sanitized_map(const PcssSettings& s) {
  return s.structure == Structure::pyramid || s.blockers != Estimator::traversal || s.occlusion != Estimator::traversal;
}

Define switch_define(const char* name, int value) { return {name, std::to_string(value)}; }

// The squares with area-weighted edges (pcss_regions.glsl's PN_AREA_EDGES; issue 51): every pass
// that reads a region (the search's cover, the scan, the traversal, the one call) compiles with it.
std::vector<Define> with_area_edges(std::vector<Define> defines, const PcssSettings& settings) {
  defines.push_back({"PN_AREA_EDGES", settings.area_edges() ? "1" : "0"});
  return defines;
}

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

PcssPipeline::PcssPipeline(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      tree_(tree),
      pyramid_(device, tree),
      mip_(device, tree),
      depth_sums_(device, tree),
      reuse_(device, tree),
      blur_(device, tree),
      search_(device, tree, "passes/pcss_search.comp"),
      traverse_(device, tree, "passes/pcss_traverse.comp"),
      filter_(device, tree, "passes/pcss_filter.comp"),
      one_call_(device, tree, "passes/pcss_one_call", PN_PCSS_VISIBILITY_IMAGE),
      scan_(device, tree, "passes/pcss_scan.comp"),
      poisson_(device, tree, "passes/pcss_poisson.comp"),
      compact_(device, tree, "passes/pcss_compact.comp"),
      shade_(device, tree, "passes/pcss_shade.comp"),
      sample_table_(device.upload(generate_sample_table(kSampleTableSeed).image())),
      no_parents_(cleared_texture(1, 1)),
      no_pyramid_(device.make_texture({TexelFormat::rgba32f, 1, 1, 1, 1, true})),
      no_mip_(device.make_texture(float_shape(1, 1, 4))),
      no_depth_sums_(device.make_texture({TexelFormat::rgba32ui, 1, 1})),
      blocker_disk_(make_disk(PcssSettings{}.blocker_samples, kPoissonBlockerDiskSeed)),
      filter_disk_(make_disk(PcssSettings{}.filter_samples, kPoissonFilterDiskSeed)) {
  const float zero[4] = {0, 0, 0, 0};
  for (const Texture* placeholder : {&no_pyramid_, &no_mip_, &no_depth_sums_}) device.clear_texture(**placeholder, zero);
  // The passes without switches now, so a copy that does not compile fails here.
  for (const ProgramVariants* pass : {&scan_, &poisson_, &compact_, &shade_}) pass->get();
}

PcssPipeline::~PcssPipeline() = default;

PcssPipeline::Texture PcssPipeline::float_texture(int size, int channels) const {
  return device_->make_texture(float_shape(size, size, channels));
}

PcssPipeline::Texture PcssPipeline::cleared_texture(int size, int channels) const {
  Texture t = float_texture(size, channels);
  const float zero[4] = {0, 0, 0, 0};
  device_->clear_texture(*t, zero);
  return t;
}

void PcssPipeline::build_structure(PcssFrame& frame, const TechniqueInputs& inputs, int n) const {
  const PcssSettings& s = frame.settings;
  const DeviceTexture& shadow_map = *inputs.shadow_map;
  const bool levels = uses_structure_levels(s);
  if (uses_sanitized_map(s)) {
    const int max_level = s.structure == Structure::pyramid && levels ? 31 : 0;
    const DepthPyramid* kept = inputs.pyramid;  // the source's, kept up to date, when it has the levels read here
    if (kept && kept->map_size == n && kept->levels >= pyramid_level_count(n, max_level)) {
      frame.pyramid = kept;
    } else {
      frame.built_pyramid = pyramid_.build(shadow_map, n, n, max_level);
      frame.pyramid = &frame.built_pyramid;
    }
  }
  if (s.structure == Structure::mip && levels) {
    if (inputs.mip && inputs.mip->map_size == n) {
      frame.mip = inputs.mip;
    } else {
      frame.built_mip = mip_.build(shadow_map, n);
      frame.mip = &frame.built_mip;
    }
    if (s.blockers == Estimator::traversal && s.depth_sums == DepthSums::table)
      frame.depth_sums = depth_sums_.build(shadow_map, n, n);
  }
}

PcssPipeline::Texture PcssPipeline::link(const DeviceTexture& entries, int size, int tile, const PcssSettings& s) const {
  ReuseParams params;
  params.sigma1 = s.sigma1;
  params.sigma2 = s.sigma2;
  params.sigma3 = s.sigma3;
  params.tile = tile;
  return reuse_.link(entries, size, size, params);
}

void PcssPipeline::add_structures(PassResources& resources, const PcssFrame& frame) const {
  resources.add_textures(
      {{PN_PCSS_PYRAMID_BINDING, frame.pyramid ? *frame.pyramid->texture : *no_pyramid_},
       {PN_PCSS_MIP_BINDING, frame.mip ? *frame.mip->texture : *no_mip_},
       {PN_PCSS_DEPTH_SUMS_BINDING, frame.depth_sums.texture ? *frame.depth_sums.texture : *no_depth_sums_},
       {PN_PCSS_SAMPLE_TABLE_BINDING, *sample_table_}});
}


void PcssPipeline::estimate(const PcssFrame& frame, PcssBlock block, const DeviceTexture& entries,
                            const DeviceTexture* parents, int tile, Estimator estimator, int samples,
                            bool wants_depth_sums, const DeviceTexture& result) const {
  const int size = frame.size;
  block.reuseTile = parents ? tile : 0;
  block.sampleCount = samples;
  block.depthSums = static_cast<std::int32_t>(wants_depth_sums ? frame.settings.depth_sums : DepthSums::none);
  if (wants_depth_sums && frame.settings.blocker_leaf_mode)  // Step 4: the blocker mean's own leaves
    block.leafMode = static_cast<std::int32_t>(*frame.settings.blocker_leaf_mode);
  // What every estimator reads.
  PassResources inputs;
  add_structures(inputs, frame);
  inputs.add_textures({{PN_PCSS_ENTRIES_BINDING, entries},
                       {PN_PCSS_PARENTS_BINDING, parents ? *parents : *no_parents_},
                       // the sanitized map, as a sampler2D; over the mip chain, the map it was built from
                       {PN_PCSS_DEPTH_MAP_BINDING, frame.pyramid ? *frame.pyramid->level0
                                                   : frame.mip ? frame.mip->built_map() : *no_mip_}});

  if (estimator == Estimator::scan) {
    // Bands of rows, ping-pong between `result` and a partner so the last band lands in `result`.
    const Texture partner = cleared_texture(size, 4);
    const int bands = (frame.pyramid->map_size + kScanBandRows - 1) / kScanBandRows;
    const DeviceTexture* target[2] = {&result, partner.get()};
    const int first = (bands - 1) % 2;
    for (int band = 0; band < bands; ++band) {
      block.bandStart = band * kScanBandRows;
      block.bandRows = kScanBandRows;
      PassResources resources = inputs;
      resources.block = query_block(block);
      resources.textures.push_back({PN_PCSS_RESULTS_BINDING, *target[(first + band + 1) % 2]});  // the previous band
      resources.images.push_back({PN_PCSS_RESULT_IMAGE, *target[(first + band) % 2]});
      device_->run(scan_.get(with_area_edges({}, frame.settings)), resources, size, size);
    }
    return;
  }

  const QueryProgram& program = estimator == Estimator::poisson ? poisson_.get() : traverse_.get(with_area_edges(traverse_defines(block), frame.settings));
  // The list holds the pixels that must compute — not lit, and representatives
  // when reuse is on — so lit pixels are skipped with or without reuse.
  const bool list = frame.settings.skip == WorkSkip::list;
  block.workMode = list ? PN_WORK_LIST : parents ? PN_WORK_BRANCH : PN_WORK_ALL;
  PassResources resources = inputs;
  resources.block = query_block(block);
  if (estimator == Estimator::poisson) resources.more_blocks.push_back(disk_block(PN_PCSS_POISSON_DISK_BINDING, disk(samples)));
  // The work list: its header (groups x, y, z; count), and room for every pixel only when listing.
  const std::size_t header = 4 * sizeof(std::uint32_t);
  const std::size_t room = list ? static_cast<std::size_t>(size) * size * 2 * sizeof(std::uint32_t) : 0;
  const std::unique_ptr<DeviceBuffer> work = device_->make_buffer(header + room);
  const std::uint32_t start[4] = {0, 1, 1, 0};
  device_->write_buffer(*work, 0, header, start);
  resources.buffers.push_back({PN_PCSS_WORK_LIST_BINDING, *work});
  resources.images.push_back({PN_PCSS_RESULT_IMAGE, result});
  if (list) {
    device_->run(compact_.get(), resources, size, size);
    device_->run_indirect(program, resources, *work);
  } else {
    device_->run(program, resources, size * size, 1);
  }
}

const glsl::PnPoissonDisk& PcssPipeline::disk(int samples) const {
  if (samples == PN_POISSON_BLOCKER_SAMPLES) return *blocker_disk_;
  if (samples == PN_POISSON_PCF_SAMPLES) return *filter_disk_;
  // A count other than the defaults gets its own disk, made once (Bridson's algorithm on the CPU:
  // not a per-frame cost an engine pays, so not inside a timed frame after the first).
  std::unique_ptr<glsl::PnPoissonDisk>& made = other_disks_[samples];
  if (!made) made = make_disk(samples, kPoissonFilterDiskSeed);
  return *made;
}

void PcssPipeline::reuse_and_estimate(PcssFrame& frame, const PcssBlock& block, StageTimes& clock,
                                      StageNames stages, const DeviceTexture& keys, const DeviceTexture& entries,
                                      int tile, Estimator estimator, int samples, bool wants_depth_sums,
                                      Texture& parents, Texture& results) const {
  if (tile > 0) parents = link(keys, frame.size, tile, frame.settings);
  clock.stage(stages.link);
  results = cleared_texture(frame.size, 4);
  estimate(frame, block, entries, tile > 0 ? parents.get() : nullptr, tile, estimator, samples, wants_depth_sums,
           *results);
  clock.stage(stages.estimate);
}

void PcssPipeline::add_representatives(PassResources& resources, PcssBlock& block, const DeviceTexture& entries,
                                       int tile, const Texture& parents, const DeviceTexture& results) const {
  block.reuseTile = tile;
  resources.block = query_block(block);
  resources.add_textures({{PN_PCSS_ENTRIES_BINDING, entries},
                          {PN_PCSS_PARENTS_BINDING, tile > 0 ? *parents : *no_parents_},
                          {PN_PCSS_RESULTS_BINDING, results}});
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

void PcssPipeline::prepare_one_call(PcssFrame& frame, OneCall call, const TechniqueInputs& inputs, PcssBlock& block,
                                    PassResources& resources) const {
  const PcssSettings& s = frame.settings;
  // What the call reads: the mip chain (and the sums table when asked) for pnFastPcss, the pyramid for
  // pnHqepcss; and the map itself (the calls skip non-finite texels as the sanitized copy's +Inf is skipped).
  if (call == OneCall::fast || call == OneCall::hqepcss)
    build_structure(frame, inputs, inputs.light.map_size);
  block = make_block(inputs.light, s);
  resources.block = query_block(block);
  add_structures(resources, frame);
  resources.add_textures({{PN_PCSS_SHADE_GBUFFER_BINDING, *inputs.gbuffer}, {PN_PCSS_DEPTH_MAP_BINDING, *inputs.shadow_map}});
  // Only the Poisson call reads its disks; the others bind the defaults (a Vogel count may exceed the block's).
  const bool poisson = call == OneCall::poisson;
  resources.more_blocks.push_back(
      disk_block(PN_PCSS_POISSON_DISK_BINDING, poisson ? disk(s.blocker_samples) : *blocker_disk_));
  resources.more_blocks.push_back(
      disk_block(PN_PCSS_POISSON_FILTER_DISK_BINDING, poisson ? disk(s.filter_samples) : *filter_disk_));
}

static_assert(static_cast<int>(OneCall::fast) == PN_ONE_CALL_FAST && static_cast<int>(OneCall::poisson) == PN_ONE_CALL_POISSON &&
                  static_cast<int>(OneCall::exact) == PN_ONE_CALL_EXACT &&
                  static_cast<int>(OneCall::hqepcss) == PN_ONE_CALL_HQEPCSS &&
                  static_cast<int>(OneCall::vogel) == PN_ONE_CALL_VOGEL,
              "OneCall is pcss_params.h's PN_ONE_CALL_*");

// The call, whether it records its work, and — for a technique's shipped settings — the engine's
// form: its pnXDefaults as constants (docs/benchmarks.md: which form each row is).
static std::vector<Define> one_call_defines(OneCall call, bool record_work, const PcssSettings& settings) {
  std::vector<Define> out{{"PN_PCSS_ONE_CALL", std::to_string(static_cast<int>(call))},
                          {"PN_PCSS_WRITE_WORK", record_work ? "true" : "false"}};
  if (shipped_call_settings(settings)) {
    out.push_back({"PN_PCSS_ENGINE_FORM", "1"});
    if (call == OneCall::fast) {  // its work budget, as an engine sets it (fast_pcss.h)
      out.push_back({"PN_FAST_PCSS_LEAF_DIVISOR", std::to_string(settings.leaf_divisor)});
      out.push_back({"PN_FAST_PCSS_LEAF_MODE", std::to_string(static_cast<int>(settings.leaf_mode))});
    }
  }
  return with_area_edges(out, settings);
}

PcssFrame PcssPipeline::run_one_call(PcssFrame frame, const TechniqueInputs& inputs, bool record_work) const {
  const int size = frame.size;
  const std::unique_ptr<StageTimes> clock = device_->stage_clock();
  clock->start();
  PcssBlock block{};
  PassResources resources;
  const OneCall call = *frame.one_call;
  prepare_one_call(frame, call, inputs, block, resources);
  clock->stage(call == OneCall::hqepcss       ? "pyramid"
               : call != OneCall::fast        ? "no structure"
               : frame.depth_sums.texture     ? "mip chain + sums"
                                              : "mip chain");
  frame.work = record_work ? float_texture(size, 4) : cleared_texture(1, 4);
  frame.fetches = record_work ? float_texture(size, 1) : cleared_texture(1, 1);
  resources.add_images({{PN_PCSS_WORK_IMAGE, *frame.work}, {PN_PCSS_FETCH_IMAGE, *frame.fetches}});
  frame.visibility = one_call_.run(ShadeStage::compute, one_call_defines(call, record_work, frame.settings), size, resources);
  clock->stage("one call");
  frame.stages = clock->read();
  return frame;
}

std::unique_ptr<DeviceTexture> PcssPipeline::run_fragment(const TechniqueInputs& inputs, const PcssSettings& settings,
                                                          int channels) const {
  PcssFrame frame = begin_frame(inputs, settings);
  const std::optional<OneCall> call = one_call(settings);
  if (!call)
    throw Error("PCSS frame '" + settings.name + "': no one call to run in a fragment shader (reuse and blur need "
                "neighbours; the other combinations are staged ablations)");
  PcssBlock block{};
  PassResources resources;
  prepare_one_call(frame, *call, inputs, block, resources);
  return one_call_.run(ShadeStage::fragment, one_call_defines(*call, true, frame.settings), frame.size, resources, channels);
}

PcssFrame PcssPipeline::run(const TechniqueInputs& inputs, const PcssSettings& settings, bool record_work) const {
  PcssFrame frame = begin_frame(inputs, settings);
  if (frame.one_call) return run_one_call(std::move(frame), inputs, record_work);
  const int size = frame.size;
  const int n = inputs.light.map_size;
  const std::unique_ptr<StageTimes> clock = device_->stage_clock();
  clock->start();

  // Step 1's structure: what Steps 3-5 read.
  build_structure(frame, inputs, n);
  clock->stage(settings.structure == Structure::pyramid ? "pyramid"
               : frame.depth_sums.texture               ? "mip chain + sums"
                                                        : "mip chain");

  // Step 3.
  const PcssBlock block = make_block(inputs.light, settings);
  frame.search_map = float_texture(size, 4);
  // Reuse keys of their own only when reuse is on and they differ from the entries (pnEntryLinkKey).
  frame.own_keys = settings.region != RegionMode::exact;
  const bool own_search_keys = frame.own_keys && settings.search_tile > 0;
  const bool own_filter_keys = frame.own_keys && settings.filter_tile > 0;
  frame.search_keys = own_search_keys ? float_texture(size, 4) : cleared_texture(1, 4);
  frame.receiver_depth = float_texture(size, 1);
  {
    PcssBlock search_block = block;
    search_block.writeKeys = own_search_keys ? 1 : 0;
    PassResources resources;
    resources.block = query_block(search_block);
    resources.add_textures({{PN_PCSS_PYRAMID_BINDING, frame.pyramid ? *frame.pyramid->texture : *no_pyramid_},
                            {PN_PCSS_MIP_BINDING, frame.mip ? *frame.mip->texture : *no_mip_},
                            {PN_PCSS_GBUFFER_BINDING, *inputs.gbuffer}});
    resources.add_images({{PN_PCSS_SEARCH_MAP_IMAGE, *frame.search_map},
                          {PN_PCSS_SEARCH_KEYS_IMAGE, *frame.search_keys},
                          {PN_PCSS_RECEIVER_DEPTH_IMAGE, *frame.receiver_depth}});
    device_->run(search_.get(with_area_edges(search_defines(search_block), settings)), resources, size, size);
  }
  clock->stage("3 search region");

  // Step 4: blockers of the representatives, then every pixel's filter region.
  reuse_and_estimate(frame, block, *clock, {"4 reuse link", "4 blockers"}, frame.search_reuse_keys(),
                     *frame.search_map, settings.search_tile, settings.blockers, settings.blocker_samples, true,
                     frame.search_parents, frame.blocker_results);
  frame.filter_map = float_texture(size, 4);
  frame.blocker_mean = float_texture(size, 1);
  frame.filter_keys = own_filter_keys ? float_texture(size, 4) : cleared_texture(1, 4);
  {
    PcssBlock filter_block = block;
    filter_block.writeKeys = own_filter_keys ? 1 : 0;
    PassResources resources;
    add_representatives(resources, filter_block, *frame.search_map, settings.search_tile, frame.search_parents,
                        *frame.blocker_results);
    resources.add_images({{PN_PCSS_FILTER_MAP_IMAGE, *frame.filter_map},
                          {PN_PCSS_BLOCKER_MEAN_IMAGE, *frame.blocker_mean},
                          {PN_PCSS_FILTER_KEYS_IMAGE, *frame.filter_keys}});
    device_->run(filter_.get(filter_defines(filter_block)), resources, size, size);
  }
  clock->stage("4 filter region");

  // Step 5: occluded fraction of the representatives, then every pixel's visibility.
  reuse_and_estimate(frame, block, *clock, {"5 reuse link", "5 occlusion"}, frame.filter_reuse_keys(),
                     *frame.filter_map, settings.filter_tile, settings.occlusion, settings.filter_samples, false,
                     frame.filter_parents, frame.occlusion_results);
  frame.visibility = float_texture(size, 1);
  {
    PcssBlock shade_block = block;
    PassResources resources;
    add_representatives(resources, shade_block, *frame.filter_map, settings.filter_tile, frame.filter_parents,
                        *frame.occlusion_results);
    resources.images.push_back({PN_PCSS_VISIBILITY_IMAGE, *frame.visibility});
    device_->run(shade_.get(), resources, size, size);
  }
  clock->stage("5 shade");

  // Step 6.
  if (settings.blur) {
    frame.settings.blur_params.pixels_per_texel = static_cast<float>(size / static_cast<double>(n));  // adaptive radius's k
    frame.blurred = blur_.run(*frame.visibility, frame.receiver_depth.get(), size, size, frame.settings.blur_params,
                              frame.filter_map.get());
  }
  clock->stage("6 blur");
  frame.stages = clock->read();
  return frame;
}

PcssStats PcssPipeline::stats(const PcssFrame& frame) const {
  const int size = frame.size;
  const auto read = [&](const PcssFrame::Texture& t) { return device_->read_texture(*t, 0, 0); };
  if (frame.one_call) {
    if (!frame.work || frame.work->shape().width != size)
      throw Error("PCSS frame '" + frame.settings.name + "': its work was not recorded");
    const Image work = read(frame.work);
    PcssStats s;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int flags = static_cast<int>(work.at(x, y, 3));
        if (flags & 4) ++s.receivers;
        if (flags & 1) ++s.searched, ++s.search_computed, s.blocker_work += work.at(x, y, 1);
        if (flags & 2) ++s.filtered, ++s.filter_computed, s.occlusion_work += work.at(x, y, 2);
      }
    s.fetches = fetch_proxy(read(frame.fetches),
                            [&](int x, int y) { return (static_cast<int>(work.at(x, y, 3)) & 4) != 0; });
    return s;
  }
  const Image search = read(frame.search_map), filter = read(frame.filter_map);
  const Image blockers = read(frame.blocker_results), occlusion = read(frame.occlusion_results);
  const bool search_reuse = frame.settings.search_tile > 0, filter_reuse = frame.settings.filter_tile > 0;
  const Image search_parents = search_reuse ? read(frame.search_parents) : Image(size, size);
  const Image filter_parents = filter_reuse ? read(frame.filter_parents) : Image(size, size);
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
