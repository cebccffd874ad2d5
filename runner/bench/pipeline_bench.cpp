#include "bench/pipeline_bench.h"

#include <iomanip>

#include "core/error.h"
#include "figures/lit_image.h"
#include "gl/texture.h"
#include "passes/surface_pass.h"
#include "metrics/ssim.h"
#include "pipeline/pcss_pipeline.h"
#include "scene/scene.h"

namespace pn {

std::vector<PipelineBenchRow> bench_pipeline(const Context& context, const SourceTree& tree, PipelineBenchSetup setup) {
  const auto& fixture = find_scene_fixture(setup.scene);
  for (int n : setup.sizes)
    if (n < 16 || n > 4096) throw Error("size " + std::to_string(n) + ": expected 16..4096");
  if (setup.repeats < 1) throw Error("repeats " + std::to_string(setup.repeats) + ": expected >= 1");
  if (setup.methods.empty()) {
    setup.methods = pcss_methods();
    for (const PcssSettings& s : fast_pcss_ablations())
      if (s.name != fast_pcss_all_off().name) setup.methods.push_back(s);
  }
  const PcssPipeline pipeline(context, tree);
  std::vector<PipelineBenchRow> rows;
  for (int n : setup.sizes) {
    const Scene scene = make_scene(fixture, n);
    const PcssInputs inputs = pipeline.render_inputs(scene, n);
    const Image surface = read_float_texture(context, SurfaceRenderer(context, tree).render(scene, n), n, n, 4);
    const size_t first = rows.size();
    Image exact;
    double exact_ms = 0.0, poisson_ms = 0.0;
    std::vector<Image> shadows;
    for (const PcssSettings& method : setup.methods) {
      const PcssMeasurement m = pipeline.measure(inputs, method, setup.repeats);
      PipelineBenchRow row;
      row.size = n;
      row.method = method.name;
      row.total_ms = m.total_ms;
      row.stage_ms = m.stage_ms;
      row.representative_fraction = m.stats.representative_fraction();
      row.work_per_receiver = m.stats.work_per_receiver();
      shadows.push_back(read_float_texture(context, m.frame.soft_shadow(), n, n, 1));
      if (method.name == exact_pcss().name) exact = shadows.back(), exact_ms = m.total_ms;
      if (method.name == poisson_pcss().name) poisson_ms = m.total_ms;
      rows.push_back(row);
    }
    for (size_t i = first; i < rows.size(); ++i) {
      if (exact_ms > 0) rows[i].speedup_vs_exact = exact_ms / rows[i].total_ms;
      if (poisson_ms > 0) rows[i].speedup_vs_poisson = poisson_ms / rows[i].total_ms;
      if (exact.width > 0) {
        rows[i].ssim_vs_exact = ssim(exact, shadows[i - first]);
        rows[i].lit_ssim_vs_exact = lit_ssim(surface, exact, shadows[i - first]);
      }
    }
  }
  return rows;
}

void print_pipeline_bench(std::ostream& out, const std::vector<PipelineBenchRow>& rows) {
  out << std::left << std::setw(6) << "size" << std::setw(22) << "method" << std::right << std::setw(11) << "total ms"
      << std::setw(10) << "x exact" << std::setw(10) << "x Poisson" << std::setw(8) << "SSIM" << std::setw(9) << "lit SSIM" << std::setw(8)
      << "repr." << std::setw(10) << "work/px" << "   stages (ms)\n";
  for (const PipelineBenchRow& r : rows) {
    out << std::left << std::setw(6) << r.size << std::setw(22) << r.method << std::right << std::fixed
        << std::setprecision(2) << std::setw(11) << r.total_ms << std::setw(10) << r.speedup_vs_exact << std::setw(10)
        << r.speedup_vs_poisson << std::setprecision(4) << std::setw(8) << r.ssim_vs_exact << std::setw(9) << r.lit_ssim_vs_exact
        << std::setprecision(3)
        << std::setw(8) << r.representative_fraction << std::setprecision(1) << std::setw(10) << r.work_per_receiver
        << "  ";
    for (const auto& [name, ms] : r.stage_ms)
      if (ms > 0.005) out << " " << name << " " << std::setprecision(2) << ms << ";";
    out << "\n";
  }
  out.unsetf(std::ios::floatfield);
}

nlohmann::json pipeline_bench_json(const PipelineBenchSetup& setup, const std::vector<PipelineBenchRow>& rows) {
  nlohmann::json list = nlohmann::json::array();
  for (const PipelineBenchRow& r : rows) {
    nlohmann::json stages = nlohmann::json::object();
    for (const auto& [name, ms] : r.stage_ms) stages[name] = ms;
    list.push_back({{"size", r.size},
                    {"method", r.method},
                    {"total_ms", r.total_ms},
                    {"stage_ms", stages},
                    {"speedup_vs_exact", r.speedup_vs_exact},
                    {"speedup_vs_poisson", r.speedup_vs_poisson},
                    {"ssim_vs_exact", r.ssim_vs_exact},
                    {"lit_ssim_vs_exact", r.lit_ssim_vs_exact},
                    {"representative_fraction", r.representative_fraction},
                    {"work_per_receiver", r.work_per_receiver}});
  }
  return {{"scene", setup.scene}, {"repeats", setup.repeats}, {"rows", list}};
}

}  // namespace pn
