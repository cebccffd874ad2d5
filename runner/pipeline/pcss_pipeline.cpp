#include "pipeline/pcss_pipeline.h"

#include <cmath>
#include <cstdint>

#include "gl/gpu_timer.h"
#include "gl/texture.h"
#include "passes/traversal_pass.h"
#include "sampling/poisson_disk.h"
#include "sampling/sample_table.h"

namespace pn {

// glsl/passes/pcss_params.glsl, std140.
struct PcssBlock {
  float light_width, light_near, light_near_plane_width, map_size, bias, filter_scale;
  std::int32_t refine_iterations, region_mode, leaf_side, leaf_mode, node_budget, reuse_tile, work_mode, band_start,
      band_rows, sample_count;
  float sigma1, sigma2, sigma3, padding;
};

namespace {

constexpr std::uint32_t kSampleTableSeed = 0x5eed0005u;
constexpr std::uint32_t kBlockerDiskSeed = 0x5eed0036u;
constexpr std::uint32_t kFilterDiskSeed = 0x5eed0064u;
constexpr int kScanBandRows = 128;  // pcss_scan.comp: 128 × ceil(8192 / 16) < 65535 loop iterations

enum WorkMode : std::int32_t { work_all = 0, work_branch = 1, work_list = 2 };

PcssBlock make_block(const LightModel& light, const PcssSettings& s) {
  PcssBlock b{};
  b.light_width = static_cast<float>(light.width);
  b.light_near = static_cast<float>(light.near_plane);
  b.light_near_plane_width = static_cast<float>(light.near_plane_width());
  b.map_size = static_cast<float>(light.map_size);
  b.bias = s.bias;
  b.filter_scale = s.filter_scale;
  b.refine_iterations = s.refine_iterations;
  b.region_mode = static_cast<std::int32_t>(s.region);
  b.leaf_side = s.leaf_side;
  b.leaf_mode = static_cast<std::int32_t>(s.leaf_mode);
  b.node_budget = s.node_budget;
  b.sigma1 = s.sigma1;
  b.sigma2 = s.sigma2;
  b.sigma3 = s.sigma3;
  return b;
}

GlObject upload_disk(const Context& context, int count, std::uint32_t seed) {
  float points[64][4] = {};  // std140 vec4 points[64]
  const PoissonDisk disk = poisson_disk(count, seed);
  for (size_t i = 0; i < disk.points.size() && i < 64; ++i) {
    points[i][0] = static_cast<float>(disk.points[i].x);
    points[i][1] = static_cast<float>(disk.points[i].y);
  }
  GlObject buffer(context, GlKind::buffer);
  context.gl().NamedBufferStorage(buffer.id(), sizeof points, points, 0);
  return buffer;
}

GlObject cleared_texture(const Context& context, int size, int channels) {
  GlObject t = make_float_texture(context, size, size, channels);
  const float zero[4] = {0, 0, 0, 0};
  context.gl().ClearTexImage(t.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT, zero);
  return t;
}

bool uses_pyramid_levels(const PcssSettings& s) {
  return s.refine_iterations > 0 || s.blockers == Estimator::traversal || s.occlusion == Estimator::traversal;
}

}  // namespace

double PcssFrame::total_ms() const {
  double sum = 0.0;
  for (const auto& stage : stages) sum += stage.second;
  return sum;
}

double PcssStats::representative_fraction() const {
  const long regions = searched + filtered;
  return regions > 0 ? static_cast<double>(search_computed + filter_computed) / static_cast<double>(regions) : 0.0;
}

double PcssStats::work_per_receiver() const {
  return receivers > 0 ? (blocker_work + occlusion_work) / static_cast<double>(receivers) : 0.0;
}

PcssPipeline::PcssPipeline(const Context& context, const SourceTree& tree)
    : context_(&context),
      shadow_map_(context, tree),
      gbuffer_(context, tree),
      pyramid_(context, tree),
      reuse_(context, tree),
      blur_(context, tree),
      search_(compile_pass(context, tree, "passes/pcss_search.comp")),
      traverse_(compile_pass(context, tree, "passes/pcss_traverse.comp")),
      scan_(compile_pass(context, tree, "passes/pcss_scan.comp")),
      poisson_(compile_pass(context, tree, "passes/pcss_poisson.comp")),
      compact_(compile_pass(context, tree, "passes/pcss_compact.comp")),
      filter_(compile_pass(context, tree, "passes/pcss_filter.comp")),
      shade_(compile_pass(context, tree, "passes/pcss_shade.comp")),
      sample_table_(upload_sample_table(context, generate_sample_table(kSampleTableSeed))),
      blocker_disk_(upload_disk(context, PcssSettings{}.blocker_samples, kBlockerDiskSeed)),
      filter_disk_(upload_disk(context, PcssSettings{}.filter_samples, kFilterDiskSeed)),
      no_parents_(cleared_texture(context, 1, 1)) {}

PcssInputs PcssPipeline::render_inputs(const Scene& scene, int screen_size) const {
  if (screen_size < 1 || screen_size > 8192)
    throw Error("screen size " + std::to_string(screen_size) + ": expected 1..8192");
  return {scene.light, screen_size, shadow_map_.render(scene), gbuffer_.render(scene, screen_size, fixtures::kNormalOffsetTexels)};
}

GlObject PcssPipeline::link(const GlObject& entries, int size, int tile, const PcssSettings& s) const {
  ReuseParams params;
  params.sigma1 = s.sigma1;
  params.sigma2 = s.sigma2;
  params.sigma3 = s.sigma3;
  params.tile = tile;
  return reuse_.link(entries, size, size, params);
}

void PcssPipeline::estimate(const PcssFrame& frame, PcssBlock block, const GlObject& entries, const GlObject* parents,
                            int tile, Estimator estimator, int samples, const GlObject& result) const {
  const auto& gl = context_->gl();
  const int size = frame.size;
  block.reuse_tile = parents ? tile : 0;
  block.sample_count = samples;
  gl.BindTextureUnit(0, frame.pyramid.texture.id());
  gl.BindTextureUnit(1, sample_table_.id());
  gl.BindTextureUnit(2, entries.id());
  gl.BindTextureUnit(4, parents ? parents->id() : no_parents_.id());

  if (estimator == Estimator::scan) {
    // Bands of rows, ping-pong between `result` and a partner so the last band lands in `result`.
    GlObject partner = cleared_texture(*context_, size, 4);
    const int bands = (frame.pyramid.map_size + kScanBandRows - 1) / kScanBandRows;
    const GlObject* target[2] = {&result, &partner};
    const int first = (bands - 1) % 2;
    for (int band = 0; band < bands; ++band) {
      block.band_start = band * kScanBandRows;
      block.band_rows = kScanBandRows;
      GlObject ubo = bind_uniform_buffer(*context_, 7, &block, sizeof block);
      const GlObject& out = *target[(first + band) % 2];
      const GlObject& previous = *target[(first + band + 1) % 2];
      gl.BindTextureUnit(5, previous.id());
      gl.BindImageTexture(3, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      scan_.dispatch(size, size);
    }
    return;
  }

  const ComputeProgram& program = estimator == Estimator::poisson ? poisson_ : traverse_;
  // The list holds the pixels that must compute — not lit, and representatives
  // when reuse is on — so lit pixels are skipped with or without reuse.
  const bool list = frame.settings.skip == WorkSkip::list;
  block.work_mode = list ? work_list : parents ? work_branch : work_all;
  GlObject ubo = bind_uniform_buffer(*context_, 7, &block, sizeof block);
  GlObject other_disk;  // a sample count other than the defaults gets its own disk
  if (estimator == Estimator::poisson) {
    const PcssSettings defaults;
    const GlObject* disk = samples == defaults.blocker_samples ? &blocker_disk_
                           : samples == defaults.filter_samples ? &filter_disk_
                                                                : nullptr;
    if (!disk) {
      other_disk = upload_disk(*context_, samples, kFilterDiskSeed);
      disk = &other_disk;
    }
    gl.BindBufferBase(GL_UNIFORM_BUFFER, 8, disk->id());
  }
  // The work list: its header (groups x, y, z; count), and room for every pixel only when listing.
  GlObject work(*context_, GlKind::buffer);
  const GLsizeiptr header = 4 * sizeof(std::uint32_t);
  const GLsizeiptr room = list ? static_cast<GLsizeiptr>(size) * size * 2 * sizeof(std::uint32_t) : 0;
  gl.NamedBufferData(work.id(), header + room, nullptr, GL_DYNAMIC_COPY);
  const std::uint32_t start[4] = {0, 1, 1, 0};
  gl.NamedBufferSubData(work.id(), 0, header, start);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, work.id());
  gl.BindImageTexture(3, result.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  if (list) {
    compact_.dispatch(size, size);
    program.dispatch_indirect(work);
  } else {
    program.dispatch(size * size, 1);
  }
}

void PcssPipeline::reuse_and_estimate(PcssFrame& frame, const PcssBlock& block, StageClock& clock,
                                      const std::string& step, const GlObject& keys, const GlObject& entries, int tile,
                                      Estimator estimator, int samples, GlObject& parents, GlObject& results) const {
  if (tile > 0) parents = link(keys, frame.size, tile, frame.settings);
  clock.stage(step + " reuse link");
  results = cleared_texture(*context_, frame.size, 4);
  estimate(frame, block, entries, tile > 0 ? &parents : nullptr, tile, estimator, samples, results);
  clock.stage(step + (step == "4" ? " blockers" : " occlusion"));
}

GlObject PcssPipeline::bind_representatives(const PcssBlock& block, const GlObject& entries, int tile,
                                            const GlObject& parents, const GlObject& results) const {
  PcssBlock b = block;
  b.reuse_tile = tile;
  GlObject ubo = bind_uniform_buffer(*context_, 7, &b, sizeof b);
  const auto& gl = context_->gl();
  gl.BindTextureUnit(2, entries.id());
  gl.BindTextureUnit(4, tile > 0 ? parents.id() : no_parents_.id());
  gl.BindTextureUnit(5, results.id());
  return ubo;
}

PcssFrame PcssPipeline::run(const PcssInputs& inputs, const PcssSettings& settings) const {
  settings.validate();
  const auto& gl = context_->gl();
  PcssFrame frame;
  frame.settings = settings;
  frame.size = inputs.screen_size;
  const int size = frame.size;
  const int n = inputs.light.map_size;
  StageClock clock(*context_);
  clock.start();

  // Step 1's pyramid: all levels when something reads them, else level 0 (the sanitized map) only.
  frame.pyramid = pyramid_.build(inputs.shadow_map, n, n, uses_pyramid_levels(settings) ? 31 : 0);
  clock.stage("pyramid");

  // Step 3.
  const PcssBlock block = make_block(inputs.light, settings);
  frame.search_map = make_float_texture(*context_, size, size, 4);
  frame.search_keys = make_float_texture(*context_, size, size, 4);
  {
    GlObject ubo = bind_uniform_buffer(*context_, 7, &block, sizeof block);
    gl.BindTextureUnit(0, frame.pyramid.texture.id());
    gl.BindTextureUnit(1, inputs.gbuffer.id());
    gl.BindImageTexture(2, frame.search_map.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl.BindImageTexture(3, frame.search_keys.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    search_.dispatch(size, size);
  }
  clock.stage("3 search region");

  // Step 4: blockers of the representatives, then every pixel's filter region.
  reuse_and_estimate(frame, block, clock, "4", frame.search_keys, frame.search_map, settings.search_tile,
                     settings.blockers, settings.blocker_samples, frame.search_parents, frame.blocker_results);
  frame.filter_map = make_float_texture(*context_, size, size, 4);
  frame.blocker_mean = make_float_texture(*context_, size, size, 1);
  frame.filter_keys = make_float_texture(*context_, size, size, 4);
  {
    GlObject ubo = bind_representatives(block, frame.search_map, settings.search_tile, frame.search_parents,
                                        frame.blocker_results);
    gl.BindImageTexture(0, frame.filter_map.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl.BindImageTexture(1, frame.blocker_mean.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    gl.BindImageTexture(2, frame.filter_keys.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    filter_.dispatch(size, size);
  }
  clock.stage("4 filter region");

  // Step 5: occluded fraction of the representatives, then every pixel's visibility.
  reuse_and_estimate(frame, block, clock, "5", frame.filter_keys, frame.filter_map, settings.filter_tile,
                     settings.occlusion, settings.filter_samples, frame.filter_parents, frame.occlusion_results);
  frame.visibility = make_float_texture(*context_, size, size, 1);
  {
    GlObject ubo = bind_representatives(block, frame.filter_map, settings.filter_tile, frame.filter_parents,
                                        frame.occlusion_results);
    gl.BindImageTexture(3, frame.visibility.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    shade_.dispatch(size, size);
  }
  clock.stage("5 shade");

  // Step 6.
  if (settings.blur) frame.blurred = blur_.run(frame.visibility, nullptr, size, size, settings.blur_params);
  clock.stage("6 blur");
  frame.stages = clock.read();
  context_->throw_if_gl_error("PCSS frame '" + settings.name + "'");
  return frame;
}

PcssStats PcssPipeline::stats(const PcssFrame& frame) const {
  const int size = frame.size;
  const auto read4 = [&](const GlObject& t) { return read_float_texture(*context_, t, size, size, 4); };
  const auto read1 = [&](const GlObject& t) { return read_float_texture(*context_, t, size, size, 1); };
  const Image search = read4(frame.search_map), filter = read4(frame.filter_map);
  const Image blockers = read4(frame.blocker_results), occlusion = read4(frame.occlusion_results);
  const bool search_reuse = frame.settings.search_tile > 0, filter_reuse = frame.settings.filter_tile > 0;
  const Image search_parents = search_reuse ? read1(frame.search_parents) : Image(size, size);
  const Image filter_parents = filter_reuse ? read1(frame.filter_parents) : Image(size, size);
  PcssStats s;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (search.at(x, y, 0) > 0.0f) ++s.receivers;
      if (search.at(x, y, 3) >= 0.0f) {
        ++s.searched;
        if (search_parents.at(x, y) == 0.0f) {
          ++s.search_computed;
          s.blocker_work += blockers.at(x, y, 3);
        }
      }
      if (filter.at(x, y, 3) >= 0.0f) {
        ++s.filtered;
        if (filter_parents.at(x, y) == 0.0f) {
          ++s.filter_computed;
          s.occlusion_work += occlusion.at(x, y, 3);
        }
      }
    }
  return s;
}

PcssMeasurement PcssPipeline::measure(const PcssInputs& inputs, const PcssSettings& settings, int repeats) const {
  if (repeats < 1) throw Error("repeats " + std::to_string(repeats) + ": expected >= 1");
  PcssMeasurement m;
  run(inputs, settings);  // untimed: the driver compiles shader variants on first use (llvmpipe: ~1 s)
  std::vector<double> totals;
  std::vector<std::vector<double>> stages;
  for (int r = 0; r < repeats; ++r) {
    m.frame = run(inputs, settings);
    totals.push_back(m.frame.total_ms());
    stages.resize(m.frame.stages.size());
    for (size_t i = 0; i < m.frame.stages.size(); ++i) stages[i].push_back(m.frame.stages[i].second);
  }
  m.total_ms = median(totals);
  for (size_t i = 0; i < stages.size(); ++i) m.stage_ms.emplace_back(m.frame.stages[i].first, median(stages[i]));
  m.stats = stats(m.frame);
  return m;
}

}  // namespace pn
