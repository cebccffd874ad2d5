#include "technique/comparison.h"

#include <algorithm>
#include <chrono>
#include <iomanip>

#include "core/error.h"
#include "core/format.h"
#include "gl/texture.h"
#include "cascades/cascaded_frame.h"
#include "pass_runners/shadow_map_pass.h"
#include "pass_runners/surface_pass.h"
#include "technique/cascaded_technique.h"
#include "technique/shadow_map_sources.h"
#include "technique/technique_registry.h"
#include "truth/ray_traced_truth.h"

namespace pn {

namespace {
constexpr const char* kTruthRow = "truth (ray traced)";

// Each pixel's cascade from the camera's view depth (z, w = surface): the first whose far end lies
// beyond it (cascades.glsl's selection), -1 where the pixel sees nothing or lies past the last.
Image cascade_index_image(const Image& view_depth, const CascadedFrame& frame) {
  Image out(view_depth.width, view_depth.height, 1, -1.0f);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      if (view_depth.at(x, y, 3) == 0.0f) continue;
      const float z = view_depth.at(x, y, 2);
      for (size_t i = 0; i < frame.cascades.size(); ++i)
        if (z < frame.cascades[i].split_far) {
          out.at(x, y) = static_cast<float>(i);
          break;
        }
    }
  return out;
}
}  // namespace

const TechniqueResult* Comparison::find(const std::string& name) const {
  for (const TechniqueResult& r : results)
    if (r.name == name) return &r;
  return nullptr;
}

Comparison compare_techniques(const Context& context, const SourceTree& tree, const Scene& scene,
                              const ComparisonSetup& setup) {
  if (setup.techniques.empty()) throw Error("no techniques to compare");
  const int size = setup.screen_size;
  const bool cascaded = scene.sun && setup.cascades;
  if (cascaded && setup.source != "full")
    throw Error("shadow-map source '" + setup.source + "' on cascades: expected full (each cascade's map is drawn whole)");
  const auto source = find_shadow_map_source(setup.source).make(context, tree, {});
  const GBufferRenderer gbuffer(context, tree);
  const SecondLayerRenderers layers(context, tree, second_layers_of(setup.techniques));
  // The frame the techniques read: one map and G-buffer, or the cascades' (each technique then
  // runs once a cascade through CascadedTechnique, and the visibilities are blended).
  SceneFrame frame;
  std::unique_ptr<CascadedFrame> cascades;
  if (cascaded)
    cascades = render_cascaded_frame(context, ShadowMapRenderer(context, tree), gbuffer, scene, *setup.cascades, size,
                                     nullptr, &layers);
  else
    frame = render_scene_frame(context, *source, gbuffer, scene, size, &layers);
  const TechniqueInputs inputs = cascaded ? cascades->inputs(scene.light) : frame.inputs();

  Comparison c;
  c.shadow_map_ms = cascaded ? cascades->shadow_map_ms : frame.shadow_map_ms;
  c.second_layer_ms = cascaded ? cascades->second_layer_ms : frame.second_layer_ms;
  if (cascaded) {
    c.cascades = cascades->cascades;
    c.cascade_index = cascade_index_image(context.read_texture(*cascades->view_depth, 0, 0), *cascades);
  }
  c.surface = read_float_texture(context, SurfaceRenderer(context, tree).render(scene, size));
  TruthSettings truth_settings;
  truth_settings.samples_per_side = setup.truth_samples;
  const auto start = std::chrono::steady_clock::now();
  c.truth = trace_truth(scene, size, truth_settings).visibility;
  c.truth_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  TechniqueResources resources(context, tree);
  const VisibilityScorer against_truth(c.truth, c.surface);
  std::vector<std::unique_ptr<Technique>> techniques, on_cascades;
  std::vector<const Technique*> timed;
  const CascadeBlendPass* blend = cascaded ? &resources.shared<CascadeBlendPass>() : nullptr;
  for (const TechniqueConfig* config : setup.techniques) {
    techniques.push_back(config->create(resources));
    if (cascaded) on_cascades.push_back(std::make_unique<CascadedTechnique>(*techniques.back(), *blend, context));
    timed.push_back(cascaded ? on_cascades.back().get() : techniques.back().get());
  }
  std::vector<TechniqueMeasurement> measurements = measure_techniques(timed, inputs, setup.repeats);
  std::vector<LoopCensus> censuses(setup.techniques.size());
  if (setup.census)
    for (size_t k = 0; k < setup.techniques.size(); ++k) {
      // Programs of its own, compiled and run while the census is the context's.
      struct CensusScope {
        const Context& context;
        CensusScope(const Context& c, LoopCensus& census) : context(c) { context.set_loop_census(&census); }
        ~CensusScope() { context.set_loop_census(nullptr); }
      } scope(context, censuses[k]);
      TechniqueResources counted(context, tree);
      const std::unique_ptr<Technique> technique = setup.techniques[k]->create(counted);
      if (cascaded) {
        const CascadedTechnique on_cascades(*technique, counted.shared<CascadeBlendPass>(), context);
        on_cascades.run(inputs, false);
      } else {
        technique->run(inputs, false);
      }
    }
  for (size_t k = 0; k < setup.techniques.size(); ++k) {
    TechniqueResult r;
    r.name = setup.techniques[k]->name();
    r.measurement = std::move(measurements[k]);
    r.census = std::move(censuses[k]);
    r.visibility = context.read_texture(*r.measurement.frame.visibility, 0, 0);
    r.vs_truth = against_truth.score(r.visibility);
    c.results.push_back(std::move(r));
  }
  if (const TechniqueResult* exact = c.find(kExactTechnique)) {
    const VisibilityScorer against_exact(exact->visibility, c.surface);
    for (TechniqueResult& r : c.results) r.vs_exact = against_exact.score(r.visibility);
    c.truth_vs_exact = against_exact.score(c.truth);
  }
  return c;
}

namespace {

void score_cells(std::ostream& out, const ImageScore& s) {
  out << std::fixed << std::setprecision(4) << std::setw(11) << s.ssim << std::setw(10) << s.mae;
}

void score_cells(std::ostream& out, const std::optional<ImageScore>& s) {
  if (s) score_cells(out, *s);
  else out << std::setw(11) << "-" << std::setw(10) << "-";
}

template <class Member>
std::optional<ImageScore> part(const std::optional<Scores>& s, Member member) {
  if (!s) return std::nullopt;
  return (*s).*member;
}

}  // namespace

int name_column_width(const std::vector<std::string>& names) {
  size_t width = std::string(kTruthRow).size();
  for (const std::string& name : names) width = std::max(width, name.size());
  return static_cast<int>(width) + 2;
}

void print_score_tables(std::ostream& out, const Comparison& c) {
  std::vector<std::string> names;
  for (const TechniqueResult& r : c.results) names.push_back(r.name);
  const int kName = name_column_width(names);
  out << "light-facing pixels (N.L > 0):\n"
      << std::left << std::setw(kName) << "technique" << std::right << std::setw(10) << "GPU ms" << std::setw(11)
      << "SSIM truth" << std::setw(10) << "MAE truth" << std::setw(11) << "SSIM exact" << std::setw(10)
      << "MAE exact" << "   stats\n";
  for (const TechniqueResult& r : c.results) {
    out << std::left << std::setw(kName) << r.name << std::right << std::fixed << std::setprecision(2) << std::setw(10)
        << format_ms(r.measurement.total_ms);
    score_cells(out, r.vs_truth.light_facing);
    score_cells(out, part(r.vs_exact, &Scores::light_facing));
    out << "  ";
    for (const auto& [name, value] : r.measurement.frame.stats)
      out << " " << name << " " << std::setprecision(value < 10 ? 3 : 1) << value;
    out << "\n";
  }
  out << std::left << std::setw(kName) << kTruthRow << std::right << std::setw(10) << "-";
  score_cells(out, ImageScore{1.0, 0.0});
  score_cells(out, part(c.truth_vs_exact, &Scores::light_facing));
  out << "   CPU " << std::setprecision(0) << c.truth_ms << " ms\n";

  out << "whole soft-shadow map | lit image:\n"
      << std::left << std::setw(kName) << "technique" << std::right;
  for (int i = 0; i < 2; ++i)
    out << std::setw(11) << "SSIM truth" << std::setw(10) << "MAE truth" << std::setw(11) << "SSIM exact"
        << std::setw(10) << "MAE exact";
  out << "\n";
  const auto row = [&](const std::string& name, const Scores& truth, const std::optional<Scores>& exact) {
    out << std::left << std::setw(kName) << name << std::right;
    score_cells(out, truth.whole);
    score_cells(out, part(exact, &Scores::whole));
    score_cells(out, truth.lit);
    score_cells(out, part(exact, &Scores::lit));
    out << "\n";
  };
  for (const TechniqueResult& r : c.results) row(r.name, r.vs_truth, r.vs_exact);
  const Scores self{{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {}};
  row(kTruthRow, self, c.truth_vs_exact);
  out.unsetf(std::ios::floatfield);
}

}  // namespace pn
