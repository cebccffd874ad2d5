#include "bench/cache_bench.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <memory>

#include "core/bounds.h"
#include "core/error.h"
#include "core/format.h"
#include "core/progress.h"
#include "draw/line_chart.h"
#include "gl/gpu_timer.h"
#include "pass_runners/gbuffer_pass.h"
#include "scene/animated_scene.h"
#include "technique/shadow_map_sources.h"
#include "technique/technique_registry.h"

namespace pn {
namespace {

constexpr const char* kFast = "fast";

const CacheBenchRow* find_row(const CacheBench& bench, int size, double k, const std::string& source) {
  for (const CacheBenchRow& r : bench.rows)
    if (r.size == size && r.k == k && r.source == source) return &r;
  return nullptr;
}

}  // namespace

void validate_cache_bench_setup(const CacheBenchSetup& setup) {
  find_animated_scene_fixture(setup.scene);
  require_list_length("sizes", setup.sizes.size());
  require_list_length("K", setup.ks.size());
  require_list_length("sources", setup.sources.size());
  if (setup.sizes.empty() || setup.ks.empty() || setup.sources.empty())
    throw Error("bench cache: expected at least one size, one K and one source");
  for (int n : setup.sizes)
    if (n < 16 || n > 4096) throw Error("map size " + std::to_string(n) + ": expected 16..4096");
  for (double k : setup.ks) validate_moving_share(k, "K");
  for (const std::string& s : setup.sources) find_shadow_map_source(s);
  if (setup.frames < 1 || setup.frames > 1000) throw Error("frames " + std::to_string(setup.frames) + ": expected 1..1000");
  if (setup.warmup < 1 || setup.warmup > 100) throw Error("warm-up frames " + std::to_string(setup.warmup) + ": expected 1..100");
  if (setup.screen < 16 || setup.screen > 4096) throw Error("screen " + std::to_string(setup.screen) + ": expected 16..4096");
  validate_animated_scene_model(setup.model);  // last: it reads the file
}

CacheBench bench_cache(const Context& context, const SourceTree& tree, const CacheBenchSetup& setup) {
  validate_cache_bench_setup(setup);
  const std::filesystem::path model = animated_scene_model(setup.model);
  const GBufferRenderer gbuffers(context, tree);
  TechniqueResources resources(context, tree);
  const std::unique_ptr<Technique> fast = parse_technique(kFast)->create(resources);
  SourceOptions options;
  options.mip_chain = true;  // what Fast PCSS reads: kept by every source, so its update is in the stage
  CacheBench bench;
  bench.scene = setup.scene + (model.empty() ? "" : " + " + model.filename().string());
  Progress progress("bench cache", setup.sizes.size() * setup.ks.size());
  for (int n : setup.sizes)
    for (double k : setup.ks) {
      progress.step(std::to_string(n) + "² K = " + format_number("%g", k));
      AnimatedScene animation(find_animated_scene_fixture(setup.scene), k, n, model);
      std::vector<std::unique_ptr<ShadowMapSource>> sources;
      for (const std::string& s : setup.sources) sources.push_back(find_shadow_map_source(s).make(context, tree, options));
      const size_t count = sources.size();
      std::vector<std::vector<double>> map_ms(count), fast_ms(count), frame_ms(count);
      std::vector<double> redrawn(count, 0.0);
      double moving = 0.0;
      for (int f = 0; f < setup.warmup + setup.frames; ++f) {
        const Scene scene = animation.frame(f);
        if (f == 0) bench.triangles = static_cast<int>(scene.triangles().size() / 3);
        const bool timed = f >= setup.warmup;
        if (timed) moving += animation.moving_share(f);
        const std::unique_ptr<DeviceTexture> gbuffer =
            gbuffers.render_texture(scene, setup.screen, fixtures::kNormalOffsetTexels, scene.map_light());
        // Each frame starts with the next source in turn, and each source's stage starts on an idle
        // GPU: work left by the one before (llvmpipe frees the textures of a technique's frame at
        // its next flush) is nobody's stage. Measured: without both, whichever source ran second
        // in every frame paid ~10 %.
        for (size_t turn = 0; turn < count; ++turn) {
          const size_t s = (turn + static_cast<size_t>(f)) % count;
          context.gl().Finish();
          StageClock clock(context);
          clock.start();
          const SourcedMap& sourced = sources[s]->render(scene);
          clock.stage("shadow map");
          const double stage_ms = clock.read().front().second;
          const TechniqueInputs inputs{scene.light, setup.screen, sourced.map, gbuffer.get(), sourced.mip, sourced.pyramid};
          const double technique_ms = fast->run(inputs, false).total_ms();
          if (!timed) continue;
          map_ms[s].push_back(stage_ms);
          fast_ms[s].push_back(technique_ms);
          frame_ms[s].push_back(stage_ms + technique_ms);
          redrawn[s] += map_share(sourced.redrawn, n);
        }
      }
      for (size_t s = 0; s < count; ++s) {
        CacheBenchRow row;
        row.size = n;
        row.k = k;
        row.moving_share = moving / setup.frames;
        row.source = setup.sources[s];
        row.map_ms = median(map_ms[s]);
        double sum = 0.0;
        for (double v : map_ms[s]) sum += v;
        row.map_mean_ms = sum / static_cast<double>(map_ms[s].size());
        row.fast_ms = median(fast_ms[s]);
        row.frame_ms = median(frame_ms[s]);
        row.redrawn_share = redrawn[s] / setup.frames;
        bench.rows.push_back(row);
      }
    }
  return bench;
}

void print_cache_bench(std::ostream& out, const CacheBench& bench) {
  out << "bench cache: '" << bench.scene << "', " << bench.triangles
      << " triangles; GPU ms a frame, medians (map mean: every frame counted); x full: the full render's over this source's\n";
  out << std::left << std::setw(7) << "map" << std::setw(6) << "K" << std::setw(8) << "moving" << std::setw(12) << "source"
      << std::right << std::setw(10) << "map ms" << std::setw(10) << "mean" << std::setw(9) << "x full" << std::setw(11)
      << "Fast PCSS" << std::setw(10) << "frame" << std::setw(9) << "x full" << std::setw(10) << "redrawn" << "\n";
  for (const CacheBenchRow& r : bench.rows) {
    const CacheBenchRow* full = find_row(bench, r.size, r.k, "full");
    const auto ratio = [](const CacheBenchRow* f, double a, double b) {
      return f && b > 0.0 && std::isfinite(a) && std::isfinite(b) ? format_number("%.2f", a / b) : std::string("-");
    };
    out << std::left << std::setw(7) << r.size << std::setw(6) << format_number("%g", r.k) << std::setw(8)
        << format_number("%.3f", r.moving_share) << std::setw(12) << r.source << std::right << std::setw(10)
        << format_ms(r.map_ms) << std::setw(10) << format_ms(r.map_mean_ms) << std::setw(9)
        << ratio(full, full ? full->map_ms : 0.0, r.map_ms) << std::setw(11) << format_ms(r.fast_ms) << std::setw(10)
        << format_ms(r.frame_ms) << std::setw(9) << ratio(full, full ? full->frame_ms : 0.0, r.frame_ms) << std::setw(9)
        << format_number("%.1f", 100.0 * r.redrawn_share) << "%\n";
  }
}

nlohmann::json cache_bench_json(const CacheBenchSetup& setup, const CacheBench& bench) {
  nlohmann::json rows = nlohmann::json::array();
  for (const CacheBenchRow& r : bench.rows)
    rows.push_back({{"map_size", r.size}, {"k", r.k}, {"moving_share", r.moving_share}, {"source", r.source},
                    {"map_ms", r.map_ms}, {"map_mean_ms", r.map_mean_ms}, {"fast_ms", r.fast_ms},
                    {"frame_ms", r.frame_ms}, {"redrawn_share", r.redrawn_share}});
  return {{"scene", bench.scene}, {"triangles", bench.triangles}, {"frames", setup.frames}, {"warmup", setup.warmup},
          {"screen", setup.screen}, {"rows", rows}};
}

Canvas cache_bench_chart(const CacheBench& bench, const std::string& title) {
  ChartPanel stage{"shadow-map stage: drawing, composition, mip chain", "K (share of moving triangles)", "GPU ms (median)", {}};
  ChartPanel frame{"whole frame: shadow-map stage + Fast PCSS", "K (share of moving triangles)", "frames per second (1000 / median ms)", {}};
  std::vector<int> sizes;
  std::vector<std::string> sources;
  for (const CacheBenchRow& r : bench.rows) {
    if (std::find(sizes.begin(), sizes.end(), r.size) == sizes.end()) sizes.push_back(r.size);
    if (std::find(sources.begin(), sources.end(), r.source) == sources.end()) sources.push_back(r.source);
  }
  const Rgb colours[] = {{90, 90, 90}, {33, 102, 172}, {200, 40, 40}, {30, 140, 60}, {150, 80, 170}};
  for (size_t z = 0; z < sizes.size(); ++z)
    for (size_t s = 0; s < sources.size(); ++s) {
      ChartSeries a{sources[s] + " " + std::to_string(sizes[z]) + "²", colours[s % std::size(colours)], z % 2 == 1, {}};
      ChartSeries b = a;
      for (const CacheBenchRow& r : bench.rows)
        if (r.size == sizes[z] && r.source == sources[s]) {
          a.points.emplace_back(r.k, r.map_ms);
          b.points.emplace_back(r.k, r.frame_ms > 0.0 ? 1000.0 / r.frame_ms : NAN);
        }
      stage.series.push_back(a);
      frame.series.push_back(b);
    }
  return draw_line_charts(title, {stage, frame});
}

}  // namespace pn
