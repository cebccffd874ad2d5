#include "bench/cascades_bench.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <tuple>

#include "cascades/cascade_math.h"
#include "cascades/cascaded_frame.h"
#include "core/bounds.h"
#include "core/error.h"
#include "core/format.h"
#include "core/named.h"
#include "core/progress.h"
#include "draw/line_chart.h"
#include "gl/texture.h"
#include "metrics/scores.h"
#include "pass_runners/shadow_map_pass.h"
#include "pass_runners/surface_pass.h"
#include "scene/city_scene.h"
#include "technique/cascaded_technique.h"
#include "technique/comparison.h"
#include "technique/technique_registry.h"
#include "truth/ray_traced_truth.h"

namespace pn {
namespace {

const fixtures::CitySceneFixture& city_fixture(const std::string& name) {
  if (const auto* f = find_city_scene_fixture_or_null(name)) return *f;
  throw Error("bench cascades scene '" + name + "': expected one of " + known_names(fixtures::kCityScenes) +
              " (a scene lit by the sun)");
}

struct Config {
  std::string sweep;
  int count, size;
  double k;
};

// The configurations of the three sweeps, each measured once even where the sweeps meet.
std::vector<Config> configs(const CascadesBenchSetup& s) {
  std::vector<Config> out;
  const auto add = [&](const char* sweep, int count, int size, double k) {
    for (const Config& c : out)
      if (c.count == count && c.size == size && c.k == k) return;
    out.push_back({sweep, count, size, k});
  };
  for (int count : s.counts) add("count", count, s.size, 1.0);
  for (int size : s.sizes) add("size", s.count, size, 1.0);
  for (double k : s.ks) add("k", s.count, s.size, k);
  return out;
}

CascadeSettings cascade_settings(int count, int size, double k, bool stable) {
  CascadeSettings c;
  c.count = count, c.map_size = size, c.enlargement = k, c.stable = stable;
  return c;
}

double mean_abs_change(const Image& now, const Image& before, const Image& covered) {
  double sum = 0;
  long n = 0;
  for (size_t i = 0; i < now.texels.size(); ++i)
    if (covered.texels[i] != 0.0f) sum += std::fabs(now.texels[i] - before.texels[i]), ++n;
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

// Whether a row is a point of the sweep: the count sweep holds the size and k = 1, the size
// sweep the count and k = 1, the k sweep the count and the size.
bool belongs(const CascadesBench& bench, const CascadesBenchRow& r, const std::string& sweep) {
  if (sweep == "count") return r.size == bench.size && r.k == 1.0;
  if (sweep == "size") return r.count == bench.count && r.k == 1.0;
  return r.count == bench.count && r.size == bench.size;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

}  // namespace

void validate_cascades_bench_setup(const CascadesBenchSetup& s) {
  city_fixture(s.scene);
  require_list_length("cascades counts", s.counts.size());
  require_list_length("cascades sizes", s.sizes.size());
  require_list_length("cascades ks", s.ks.size());
  require_list_length("techniques", s.techniques.size());
  require_list_length("path techniques", s.path_techniques.size());
  for (int c : s.counts)
    if (c < 0 || c > PN_CASCADES_MAX) throw Error("cascade count " + std::to_string(c) + ": expected 0 (one map) .. 4");
  if (s.count < 1 || s.count > PN_CASCADES_MAX) throw Error("cascade count " + std::to_string(s.count) + ": expected 1..4");
  for (int n : s.sizes)
    if (n < 16 || n > 4096) throw Error("size " + std::to_string(n) + ": expected 16..4096");
  if (s.size < 16 || s.size > 4096) throw Error("size " + std::to_string(s.size) + ": expected 16..4096");
  for (double k : s.ks) cascade_settings(s.count, s.size, k, true).validate();
  if (s.path_frames < 2 || s.path_frames > 200) throw Error("path frames " + std::to_string(s.path_frames) + ": expected 2..200");
  if (s.screen < 16 || s.screen > 4096) throw Error("screen size " + std::to_string(s.screen) + ": expected 16..4096");
  if (s.repeats < 1 || s.repeats > 100) throw Error("repeats " + std::to_string(s.repeats) + ": expected 1..100");
  if (s.truth_samples < 1 || s.truth_samples > 64)
    throw Error("truth samples " + std::to_string(s.truth_samples) + ": expected 1..64 per side");
  for (const auto& list : {s.techniques, s.path_techniques})
    for (const std::string& m : list) parse_technique(m)->validate();
}

CascadesBench bench_cascades(const Context& context, const SourceTree& tree, const CascadesBenchSetup& setup) {
  validate_cascades_bench_setup(setup);
  const auto& fixture = city_fixture(setup.scene);
  CascadesBench bench;
  bench.scene = fixture.name;
  bench.count = setup.count, bench.size = setup.size;
  std::vector<std::unique_ptr<TechniqueConfig>> techniques;
  std::vector<const TechniqueConfig*> chosen;
  for (const std::string& m : setup.techniques) techniques.push_back(parse_technique(m)), chosen.push_back(techniques.back().get());
  const std::vector<Config> all = configs(setup);
  const Scene city = make_city_scene(fixture, setup.size);  // its models read once
  bench.triangles = static_cast<int>(city.triangles().size() / 3);
  Progress progress("bench cascades", all.size() + 2);
  for (const Config& c : all) {
    progress.step(c.count == 0 ? "one map " + std::to_string(c.size) + "²"
                               : std::to_string(c.count) + " cascades of " + std::to_string(c.size) + "², k " +
                                     format_number("%g", c.k));
    const Scene scene = with_shadow_map_size(city, c.size);
    ComparisonSetup cs;
    cs.screen_size = setup.screen, cs.repeats = setup.repeats, cs.truth_samples = setup.truth_samples;
    cs.techniques = chosen;
    if (c.count > 0) cs.cascades = cascade_settings(c.count, c.size, c.k, true);
    const Comparison result = compare_techniques(context, tree, scene, cs);
    for (const TechniqueResult& r : result.results)
      bench.rows.push_back({c.sweep, c.count, c.size, c.k, result.shadow_map_ms, r.name, r.measurement.total_ms,
                            result.shadow_map_ms + r.measurement.total_ms, r.vs_truth.light_facing.ssim,
                            r.vs_truth.light_facing.mae});
  }

  std::stable_sort(bench.rows.begin(), bench.rows.end(), [](const CascadesBenchRow& a, const CascadesBenchRow& b) {
    return std::tie(a.count, a.size, a.k) < std::tie(b.count, b.size, b.k);
  });

  // Along the path: the city and the view stand still while the cascades are fitted to the
  // camera a step and a turn further each frame, so that every change is the cascades' own.
  TechniqueResources resources(context, tree);
  std::vector<std::unique_ptr<TechniqueConfig>> path_configs;
  std::vector<std::unique_ptr<Technique>> path_techniques;
  for (const std::string& m : setup.path_techniques) {
    path_configs.push_back(parse_technique(m));
    path_techniques.push_back(path_configs.back()->create(resources));
  }
  const CascadeBlendPass& blend = resources.shared<CascadeBlendPass>();
  const ShadowMapRenderer maps(context, tree);
  const GBufferRenderer gbuffer(context, tree);
  const Scene& scene = city;
  TruthSettings truth_settings;
  truth_settings.samples_per_side = setup.truth_samples;
  truth_settings.progress = false;
  const int n = setup.screen;
  const Truth truth = trace_truth(scene, n, truth_settings);
  const VisibilityScorer scorer(truth.visibility, read_float_texture(context, SurfaceRenderer(context, tree).render(scene, n)));
  std::vector<const TechniqueConfig*> path_list;
  for (const auto& c : path_configs) path_list.push_back(c.get());
  const SecondLayerRenderers layers(context, tree, second_layers_of(path_list));
  for (bool stable : {true, false}) {
    progress.step(std::string(stable ? "stable" : "unstable") + " cascades along the camera path, " +
                  std::to_string(setup.path_frames) + " frames");
    std::vector<CascadesPathRow> rows(path_techniques.size());
    std::vector<Image> before(rows.size());
    for (int f = 0; f < setup.path_frames; ++f) {
      const SceneCamera fitted = city_camera(f);
      const auto frame = render_cascaded_frame(context, maps, gbuffer, scene,
                                               cascade_settings(setup.count, setup.size, 1.0, stable), n, &fitted,
                                               &layers);
      for (size_t m = 0; m < rows.size(); ++m) {
        Image v = context.read_texture(*CascadedTechnique(*path_techniques[m], blend, context).run(frame->inputs(scene.light), false).visibility, 0, 0);
        rows[m].technique = path_configs[m]->name();
        rows[m].stable = stable;
        rows[m].mean_error += scorer.score(v).light_facing.mae / setup.path_frames;
        if (f > 0) rows[m].changes.push_back(mean_abs_change(v, before[m], truth.covered));
        before[m] = std::move(v);
      }
    }
    for (CascadesPathRow& r : rows) {
      r.mean_change = mean(r.changes);
      bench.path.push_back(std::move(r));
    }
  }
  return bench;
}

void print_cascades_bench(std::ostream& out, const CascadesBench& bench) {
  out << "scene " << bench.scene << ", " << bench.triangles << " triangles; GPU ms (medians), scores against the truth on "
      << "light-facing pixels\n";
  for (const char* sweep : {"count", "size", "k"}) {
    out << "by " << sweep << ":\n"
        << std::left << std::setw(8) << "count" << std::setw(7) << "size" << std::setw(5) << "k" << std::setw(18)
        << "technique" << std::right << std::setw(10) << "maps ms" << std::setw(13) << "technique ms" << std::setw(10)
        << "frame ms" << std::setw(8) << "SSIM" << std::setw(9) << "MAE" << "\n";
    for (const CascadesBenchRow& r : bench.rows) {
      if (!belongs(bench, r, sweep)) continue;
      out << std::left << std::setw(8) << (r.count == 0 ? "1 map" : std::to_string(r.count)) << std::setw(7) << r.size
          << std::setw(5) << format_number("%g", r.k) << std::setw(18) << r.technique << std::right << std::fixed
          << std::setprecision(2) << std::setw(10) << r.maps_ms << std::setw(13) << r.technique_ms << std::setw(10)
          << r.frame_ms << std::setprecision(4) << std::setw(8) << r.ssim << std::setw(9) << r.mae << "\n";
    }
  }
  out << "cascades fitted along the camera path, seen from its first frame: mean |change| between consecutive frames "
         "(covered pixels), mean MAE vs the truth\n"
      << std::left << std::setw(22) << "technique" << std::setw(10) << "cascades" << std::right << std::setw(12) << "|change|"
      << std::setw(10) << "MAE" << "\n";
  for (const CascadesPathRow& r : bench.path)
    out << std::left << std::setw(22) << r.technique << std::setw(10) << (r.stable ? "stable" : "unstable") << std::right
        << std::fixed << std::setprecision(5) << std::setw(12) << r.mean_change << std::setw(10) << r.mean_error << "\n";
  out.unsetf(std::ios::floatfield);
}

nlohmann::json cascades_bench_json(const CascadesBenchSetup& s, const CascadesBench& bench) {
  nlohmann::json rows = nlohmann::json::array(), path = nlohmann::json::array();
  for (const CascadesBenchRow& r : bench.rows)
    rows.push_back({{"sweep", r.sweep}, {"count", r.count}, {"size", r.size}, {"k", r.k}, {"maps_ms", r.maps_ms},
                    {"technique", r.technique}, {"technique_ms", r.technique_ms}, {"frame_ms", r.frame_ms}, {"ssim", r.ssim},
                    {"mae", r.mae}});
  for (const CascadesPathRow& r : bench.path)
    path.push_back({{"technique", r.technique}, {"stable", r.stable}, {"mean_change", r.mean_change},
                    {"mean_error", r.mean_error}, {"changes", r.changes}});
  return {{"scene", bench.scene}, {"triangles", bench.triangles}, {"screen", s.screen}, {"repeats", s.repeats},
          {"truth_samples", s.truth_samples}, {"count", s.count}, {"size", s.size}, {"path_frames", s.path_frames},
          {"rows", rows}, {"path", path}};
}

Canvas cascades_bench_chart(const CascadesBench& bench, const std::string& title) {
  static const Rgb colours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14}, {23, 190, 207}};
  std::vector<std::string> techniques;
  for (const CascadesBenchRow& r : bench.rows)
    if (std::find(techniques.begin(), techniques.end(), r.technique) == techniques.end()) techniques.push_back(r.technique);
  ChartPanel by_count{"frame time against split count", "cascades (0: one map)", "GPU ms", {}};
  ChartPanel by_size{"frame time against map size", "map size N", "GPU ms", {}};
  for (size_t m = 0; m < techniques.size(); ++m) {
    ChartSeries count_series{techniques[m], colours[m % 6], false, {}}, size_series{techniques[m], colours[m % 6], false, {}};
    for (const CascadesBenchRow& r : bench.rows) {
      if (r.technique != techniques[m]) continue;
      if (belongs(bench, r, "count")) count_series.points.push_back({static_cast<double>(r.count), r.frame_ms});
      if (belongs(bench, r, "size")) size_series.points.push_back({static_cast<double>(r.size), r.frame_ms});
    }
    std::sort(count_series.points.begin(), count_series.points.end());
    std::sort(size_series.points.begin(), size_series.points.end());
    by_count.series.push_back(count_series);
    by_size.series.push_back(size_series);
  }
  ChartPanel path{"change between frames along the path (dashed: unstable)", "frame", "mean |change|", {}};
  for (const CascadesPathRow& r : bench.path) {  // each technique in its colour of the other panels
    if (std::find(techniques.begin(), techniques.end(), r.technique) == techniques.end()) techniques.push_back(r.technique);
    const size_t colour = static_cast<size_t>(std::find(techniques.begin(), techniques.end(), r.technique) - techniques.begin());
    ChartSeries s{r.technique + (r.stable ? ", stable" : ", unstable"), colours[colour % 6], !r.stable, {}};
    for (size_t f = 0; f < r.changes.size(); ++f) s.points.push_back({static_cast<double>(f + 1), r.changes[f]});
    path.series.push_back(s);
  }
  return draw_line_charts(title, {by_count, by_size, path});
}

}  // namespace pn
