#include "bench/sweep_bench.h"

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "bench/bench_json.h"
#include "core/bounds.h"
#include "core/error.h"
#include "core/format.h"
#include "core/progress.h"
#include "scene/model.h"
#include "technique/technique_registry.h"

namespace pn {

bool is_exact_technique(const std::string& name) { return name.substr(0, name.find(':')) == kExactTechnique; }

Scene sweep_scene(const fixtures::SceneFixture& fixture, int size, double factor) {
  Scene scene = make_scene(fixture, size);
  scale_light_width(scene, factor, "light width factor");
  return scene;
}

Scene sweep_scene(const std::filesystem::path& model, int size, double factor) {
  Scene scene = make_model_scene(model, size);
  scale_light_width(scene, factor, "light width factor");
  return scene;
}

namespace {

// A point's scene: the setup's model, or the fixture `name`.
Scene sweep_point_scene(const SweepBenchSetup& s, const std::string& name, int size, double factor) {
  return s.model.empty() ? sweep_scene(find_scene_fixture(name), size, factor) : sweep_scene(s.model, size, factor);
}

}  // namespace

void validate_width_bench_settings(const std::vector<int>& sizes, int repeats, int truth_samples, double exact_up_to) {
  for (int n : sizes)
    if (n < 16 || n > 4096) throw Error("size " + std::to_string(n) + ": expected 16..4096");
  if (repeats < 1 || repeats > 100) throw Error("repeats " + std::to_string(repeats) + ": expected 1..100");
  if (truth_samples < 1 || truth_samples > 64)
    throw Error("truth samples " + std::to_string(truth_samples) + ": expected 1..64 per side");
  if (!(exact_up_to > 0))
    throw Error("exact up to " + format_number("%g", exact_up_to) + ": expected a light width factor > 0");
}

void validate_sweep_setup(const SweepBenchSetup& s) {
  require_list_length("sweep scenes", s.scenes.size());
  require_list_length("sweep light width factors", s.factors.size());
  require_list_length("sweep sizes", s.sizes.size());
  validate_width_bench_settings(s.sizes, s.repeats, s.truth_samples, s.exact_up_to);
  for (const std::string& name : s.scenes)
    for (double f : s.factors) sweep_point_scene(s, name, 16, f);  // the factor and the scaled light (the model read), without GL
  for (const auto& m : s.techniques) m->validate();
}

std::optional<TimeGrowth> time_growth(const std::vector<std::pair<double, double>>& factor_ms) {
  std::vector<std::pair<double, double>> counted;
  for (const auto& p : factor_ms)
    if (std::isfinite(p.second) && p.second > 0) counted.push_back(p);
  if (counted.size() < 2) return std::nullopt;
  return TimeGrowth{counted.front().first, counted.back().first, counted.back().second / counted.front().second};
}

SweepBench bench_sweep(const Context& context, const SourceTree& tree, const SweepBenchSetup& setup) {
  validate_sweep_setup(setup);
  std::vector<std::unique_ptr<TechniqueConfig>> own;
  const std::vector<const TechniqueConfig*> all = chosen_or_default_techniques(setup.techniques, render_techniques(), own);

  SweepBench bench;
  bench.exact_up_to = setup.exact_up_to;
  bench.estimate = setup.estimate;
  std::optional<GpuEstimator> estimator;
  if (setup.estimate) estimator.emplace(tree, *setup.estimate);
  for (const TechniqueConfig* c : all) bench.techniques.push_back(c->name());
  Progress progress("bench sweep", setup.scenes.size() * setup.sizes.size() * setup.factors.size());
  for (const std::string& name : setup.scenes) {
    for (int n : setup.sizes)
      for (double factor : setup.factors) {
        progress.step(name + " " + std::to_string(n) + " x" + format_number("%g", factor));
        ComparisonSetup cs;
        cs.screen_size = n;
        cs.repeats = setup.repeats;
        cs.truth_samples = setup.truth_samples;
        cs.census = estimator.has_value();
        for (const TechniqueConfig* c : all)
          if (factor <= setup.exact_up_to || !is_exact_technique(c->name())) cs.techniques.push_back(c);
        if (cs.techniques.empty()) continue;  // only exact PCSS was asked for, and not at this factor
        SweepPoint p;
        p.scene = name;
        p.size = n;
        p.factor = factor;
        const Scene scene = sweep_point_scene(setup, name, n, factor);
        p.light_width = scene.light.width;
        p.comparison = compare_techniques(context, tree, scene, cs);
        if (estimator) {
          p.estimates = estimator->estimate(p.comparison);
          p.estimate_vs_poisson = estimate_ratios(p.comparison, p.estimates, kPoissonTechnique);
        }
        bench.points.push_back(std::move(p));
      }
  }
  return bench;
}

namespace {

// The scenes, sizes and factors in sweep order (points may be missing where nothing ran).
template <class F>
void for_each_group(const SweepBench& bench, F f) {
  std::vector<std::pair<std::string, int>> groups;
  for (const SweepPoint& p : bench.points)
    if (std::find(groups.begin(), groups.end(), std::make_pair(p.scene, p.size)) == groups.end())
      groups.emplace_back(p.scene, p.size);
  for (const auto& [scene, size] : groups) {
    std::vector<const SweepPoint*> points;
    for (const SweepPoint& p : bench.points)
      if (p.scene == scene && p.size == size) points.push_back(&p);
    f(scene, size, points);
  }
}

std::string factor_text(double f) { return format_number("%g", f); }

}  // namespace

std::optional<TimeGrowth> sweep_time_growth(const SweepBench& bench, const std::string& scene, int size,
                                            const std::string& technique) {
  std::vector<std::pair<double, double>> factor_ms;
  for (const SweepPoint& p : bench.points)
    if (p.scene == scene && p.size == size)
      if (const TechniqueResult* r = p.comparison.find(technique)) factor_ms.emplace_back(p.factor, r->measurement.total_ms);
  return time_growth(factor_ms);
}

void print_sweep_bench(std::ostream& out, const SweepBench& bench) {
  const int kName = name_column_width(bench.techniques);
  for_each_group(bench, [&](const std::string& scene, int size, const std::vector<const SweepPoint*>& points) {
    out << "scene " << scene << ", " << size << "x" << size << " (shadow map = screen); light-facing pixels:\n"
        << std::right << std::setw(7) << "factor" << std::setw(8) << "width" << "  " << std::left << std::setw(kName)
        << "technique" << std::right << std::setw(11) << "GPU ms" << std::setw(11) << "SSIM truth" << std::setw(10)
        << "MAE truth" << std::setw(11) << "SSIM exact" << std::setw(10) << "MAE exact";
    if (bench.estimate) out << std::setw(11) << "est. us" << std::setw(10) << "est. x P.";
    out << "\n";
    for (const SweepPoint* p : points) {
      for (const std::string& technique : bench.techniques) {
        out << std::right << std::setw(7) << factor_text(p->factor) << std::fixed << std::setprecision(2)
            << std::setw(8) << p->light_width << "  " << std::left << std::setw(kName) << technique << std::right;
        const TechniqueResult* r = p->comparison.find(technique);
        if (!r) {
          out << "    not run (above --exact-up-to " << factor_text(bench.exact_up_to) << ")\n";
          continue;
        }
        out << std::setw(11) << r->measurement.total_ms << std::setprecision(4) << std::setw(11)
            << r->vs_truth.light_facing.ssim << std::setw(10) << r->vs_truth.light_facing.mae;
        if (r->vs_exact)
          out << std::setw(11) << r->vs_exact->light_facing.ssim << std::setw(10) << r->vs_exact->light_facing.mae;
        else
          out << std::setw(11) << "-" << std::setw(10) << "-";
        if (bench.estimate) {
          print_estimate_cells(out, p->estimates, p->estimate_vs_poisson,
                               static_cast<std::size_t>(r - p->comparison.results.data()));
          out << std::setprecision(2);
        }
        out << "\n";
      }
      out << std::right << std::setw(7) << factor_text(p->factor) << std::fixed << std::setprecision(2) << std::setw(8)
          << p->light_width << "  " << std::left << std::setw(kName) << "truth (ray traced)" << std::right
          << std::setprecision(0) << std::setw(11) << p->comparison.truth_ms << " CPU ms\n";
    }
    out << "time growth from the first to the last factor:";
    for (const std::string& technique : bench.techniques) {
      out << "  " << technique << " ";
      if (const auto g = sweep_time_growth(bench, scene, size, technique))
        out << std::setprecision(2) << g->ratio << "x (x" << factor_text(g->from) << " -> x" << factor_text(g->to)
            << ")";
      else
        out << "-";
    }
    out << "\n";
    out.unsetf(std::ios::floatfield);
    if (bench.estimate) {
      std::vector<GpuEstimate> all;
      for (const SweepPoint* p : points) all.insert(all.end(), p->estimates.begin(), p->estimates.end());
      print_estimate_note(out, *bench.estimate, all);
    }
  });
}

namespace {

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json sweep_bench_json(const SweepBenchSetup& setup, const SweepBench& bench) {
  nlohmann::json rows = nlohmann::json::array(), truth = nlohmann::json::array(), growth = nlohmann::json::array();
  for (const SweepPoint& p : bench.points) {
    for (const std::string& technique : bench.techniques) {
      nlohmann::json row{{"scene", p.scene}, {"size", p.size}, {"factor", p.factor}, {"light_width", p.light_width},
                         {"technique", technique}};
      const TechniqueResult* r = p.comparison.find(technique);
      row["ran"] = r != nullptr;
      if (r) {
        row["total_ms"] = r->measurement.total_ms;
        row["stage_ms"] = named_json(r->measurement.stage_ms);
        row["stats"] = named_json(r->measurement.frame.stats);
        row["vs_truth"] = scores_json(r->vs_truth);
        row["vs_exact"] = r->vs_exact ? scores_json(*r->vs_exact) : nlohmann::json(nullptr);
        const std::size_t k = static_cast<std::size_t>(r - p.comparison.results.data());
        if (setup.estimate && k < p.estimates.size()) {
          row["gpu_estimate"] = gpu_estimate_json(p.estimates[k], *setup.estimate);
          row["estimate_speedup_vs_poisson"] = ratio_json(p.estimate_vs_poisson[k]);
        }
      }
      rows.push_back(row);
    }
    truth.push_back({{"scene", p.scene},
                     {"size", p.size},
                     {"factor", p.factor},
                     {"light_width", p.light_width},
                     {"cpu_ms", p.comparison.truth_ms},
                     {"shadow_map_ms", p.comparison.shadow_map_ms},
                     {"second_layer_ms", p.comparison.second_layer_ms},
                     {"vs_exact", p.comparison.truth_vs_exact ? scores_json(*p.comparison.truth_vs_exact)
                                                              : nlohmann::json(nullptr)}});
  }
  for_each_group(bench, [&](const std::string& scene, int size, const std::vector<const SweepPoint*>&) {
    for (const std::string& technique : bench.techniques)
      if (const auto g = sweep_time_growth(bench, scene, size, technique))
        growth.push_back({{"scene", scene}, {"size", size}, {"technique", technique}, {"from", g->from}, {"to", g->to},
                          {"ratio", g->ratio}});
  });
  return {{"scenes", setup.scenes},     {"factors", setup.factors},
          {"sizes", setup.sizes},       {"repeats", setup.repeats},
          {"truth_samples", setup.truth_samples}, {"exact_up_to", finite_or_null(setup.exact_up_to)},
          {"techniques", bench.techniques},   {"rows", rows},
          {"truth", truth},             {"time_growth", growth}};
}

}  // namespace pn
