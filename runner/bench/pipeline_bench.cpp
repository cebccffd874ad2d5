#include "bench/pipeline_bench.h"

#include <iomanip>

#include "bench/bench_json.h"
#include "core/bounds.h"
#include "core/error.h"
#include "core/progress.h"
#include "scene/model.h"
#include "scene/scene.h"
#include "technique/technique_registry.h"

namespace pn {

namespace {

Scene bench_scene(const PipelineBenchSetup& setup, int n) {
  return setup.model.empty() ? make_scene(find_scene_fixture(setup.scene), n) : make_model_scene(setup.model, n);
}

std::string scene_name(const PipelineBenchSetup& setup) {
  return setup.model.empty() ? setup.scene : setup.model.stem().string();
}

}  // namespace

void validate_pipeline_bench_setup(const PipelineBenchSetup& setup) {
  bench_scene(setup, 16);  // an unknown scene or a model file that does not load, before any GL work
  require_list_length("pipeline sizes", setup.sizes.size());
  for (int n : setup.sizes)
    if (n < 16 || n > 4096) throw Error("size " + std::to_string(n) + ": expected 16..4096");
  if (setup.repeats < 1 || setup.repeats > 100)
    throw Error("repeats " + std::to_string(setup.repeats) + ": expected 1..100");
  if (setup.truth_samples < 1 || setup.truth_samples > 64)
    throw Error("truth samples " + std::to_string(setup.truth_samples) + ": expected 1..64 per side");
}

std::vector<PipelineBenchSize> bench_pipeline(const Context& context, const SourceTree& tree,
                                              const PipelineBenchSetup& setup) {
  validate_pipeline_bench_setup(setup);
  std::vector<std::unique_ptr<TechniqueConfig>> own;
  ComparisonSetup cs;
  cs.repeats = setup.repeats;
  cs.truth_samples = setup.truth_samples;
  cs.techniques = chosen_or_default_techniques(setup.techniques, bench_techniques(), own);
  cs.census = setup.estimate.has_value();
  std::optional<GpuEstimator> estimator;
  if (setup.estimate) estimator.emplace(tree, *setup.estimate);

  std::vector<PipelineBenchSize> out;
  Progress progress("bench pipeline", setup.sizes.size());
  for (int n : setup.sizes) {
    progress.step(scene_name(setup) + " " + std::to_string(n) + ": " + std::to_string(cs.techniques.size()) +
                  " techniques, the truth");
    cs.screen_size = n;
    PipelineBenchSize s;
    s.size = n;
    s.comparison = compare_techniques(context, tree, bench_scene(setup, n), cs);
    const TechniqueResult* exact = s.comparison.find(kExactTechnique);
    const TechniqueResult* poisson = s.comparison.find(kPoissonTechnique);
    const TechniqueResult* staged = s.comparison.find(kStagedPoissonTechnique);
    const auto ratio = [](const TechniqueResult* base, const TechniqueResult& r) {
      return base ? base->measurement.total_ms / r.measurement.total_ms : 0.0;
    };
    if (estimator) s.estimates = estimator->estimate(s.comparison);
    s.estimate_vs_poisson = estimate_ratios(s.comparison, s.estimates, kPoissonTechnique);
    for (const TechniqueResult& r : s.comparison.results) {
      s.speedup_vs_exact.push_back(ratio(exact, r));
      s.speedup_vs_poisson.push_back(ratio(poisson, r));
      s.speedup_vs_staged_poisson.push_back(ratio(staged, r));
    }
    out.push_back(std::move(s));
  }
  return out;
}

void print_pipeline_bench(std::ostream& out, const std::vector<PipelineBenchSize>& sizes,
                          const std::optional<GpuEstimateSetup>& estimate) {
  for (const PipelineBenchSize& s : sizes) {
    out << "size " << s.size << " (shadow map = screen), shadow map " << std::fixed << std::setprecision(2)
        << s.comparison.shadow_map_ms << " ms";
    if (s.comparison.second_layer_ms > 0.0) out << ", second layers " << s.comparison.second_layer_ms << " ms";
    out << ":\n";
    std::vector<std::string> names;
    for (const TechniqueResult& r : s.comparison.results) names.push_back(r.name);
    const int name = name_column_width(names);
    const bool staged = s.comparison.find(kStagedPoissonTechnique) != nullptr;
    out << std::left << std::setw(name) << "technique" << std::right << std::setw(11) << "total ms" << std::setw(10)
        << "x exact" << std::setw(10) << "x Poisson" << (staged ? "  x staged P." : "");
    if (estimate) out << std::setw(11) << "est. us" << std::setw(10) << "est. x P.";
    out << "   stages (ms)\n";
    // A baseline that did not run: "-", not a ratio of 0 (issue 54 X15).
    const auto cell = [&](int width, double ratio) {
      if (ratio > 0) out << std::setw(width) << ratio;
      else out << std::setw(width) << "-";
    };
    for (size_t i = 0; i < s.comparison.results.size(); ++i) {
      const TechniqueResult& r = s.comparison.results[i];
      out << std::left << std::setw(name) << r.name << std::right << std::fixed << std::setprecision(2) << std::setw(11)
          << r.measurement.total_ms;
      cell(10, s.speedup_vs_exact[i]);
      cell(10, s.speedup_vs_poisson[i]);
      if (staged) cell(13, s.speedup_vs_staged_poisson[i]);
      if (estimate) print_estimate_cells(out, s.estimates, s.estimate_vs_poisson, i);
      out << "  ";
      for (const auto& [name, ms] : r.measurement.stage_ms)
        if (ms > 0.005) out << " " << name << " " << ms << ";";
      out << "\n";
    }
    out.unsetf(std::ios::floatfield);
    if (estimate) print_estimate_note(out, *estimate, s.estimates);
    print_score_tables(out, s.comparison);
  }
}

nlohmann::json pipeline_bench_json(const PipelineBenchSetup& setup, const std::vector<PipelineBenchSize>& sizes) {
  nlohmann::json list = nlohmann::json::array();
  for (const PipelineBenchSize& s : sizes)
    for (size_t i = 0; i < s.comparison.results.size(); ++i) {
      const TechniqueResult& r = s.comparison.results[i];
      list.push_back({{"size", s.size},
                      {"technique", r.name},
                      {"total_ms", r.measurement.total_ms},
                      {"stage_ms", named_json(r.measurement.stage_ms)},
                      {"stats", named_json(r.measurement.frame.stats)},
                      {"speedup_vs_exact", ratio_json(s.speedup_vs_exact[i])},
                      {"speedup_vs_poisson", ratio_json(s.speedup_vs_poisson[i])},
                      {"speedup_vs_staged_poisson", ratio_json(s.speedup_vs_staged_poisson[i])},
                      {"vs_truth", scores_json(r.vs_truth)},
                      {"vs_exact", r.vs_exact ? scores_json(*r.vs_exact) : nlohmann::json(nullptr)}});
      if (setup.estimate && i < s.estimates.size()) {
        list.back()["gpu_estimate"] = gpu_estimate_json(s.estimates[i], *setup.estimate);
        list.back()["estimate_speedup_vs_poisson"] = ratio_json(s.estimate_vs_poisson[i]);
      }
    }
  nlohmann::json truth = nlohmann::json::array();
  for (const PipelineBenchSize& s : sizes)
    truth.push_back({{"size", s.size},
                     {"cpu_ms", s.comparison.truth_ms},
                     {"vs_exact", s.comparison.truth_vs_exact ? scores_json(*s.comparison.truth_vs_exact) : nlohmann::json(nullptr)}});
  return {{"scene", scene_name(setup)}, {"repeats", setup.repeats}, {"truth_samples", setup.truth_samples},
          {"rows", list}, {"truth", truth}};
}

}  // namespace pn
