#include "render/render_job.h"

#include <iomanip>

#include "core/error.h"
#include "figures/canvas.h"
#include "figures/lit_image.h"
#include "gl/texture.h"
#include "metrics/ssim.h"
#include "passes/physical_reference_pass.h"
#include "passes/surface_pass.h"
#include "pipeline/pcss_pipeline.h"
#include "scene/scene.h"

namespace pn {

void validate_render_setup(const RenderSetup& s) {
  find_scene_fixture(s.scene);
  if (s.map_size < 16 || s.map_size > 4096) throw Error("shadow-map size " + std::to_string(s.map_size) + ": expected 16..4096");
  if (s.screen_size < 16 || s.screen_size > 4096) throw Error("screen size " + std::to_string(s.screen_size) + ": expected 16..4096");
  if (s.light_samples < 1 || s.light_samples > 64) throw Error("light samples " + std::to_string(s.light_samples) + ": expected 1..64 per side");
  if (s.repeats < 1 || s.repeats > 100) throw Error("repeats " + std::to_string(s.repeats) + ": expected 1..100");
  if (s.methods.empty()) throw Error("no methods to render");
  for (const PcssSettings& m : s.methods) m.validate();
}

void create_output_directory(const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw Error("output directory '" + out.string() + "': cannot be created (" + ec.message() + ")");
}

namespace {

void write_grey(const Image& image, const std::filesystem::path& path) {
  Canvas canvas(image.width, image.height, {0, 0, 0});
  canvas.grey(flip_rows(image), 0, 0, 0, 1, 0.0f, 1.0f, {255, 0, 255});
  canvas.write_png(path);
}

void write_rgb(const Image& image, const std::filesystem::path& path) {
  Canvas canvas(image.width, image.height, {0, 0, 0});
  canvas.rgb(flip_rows(image), 0, 0, 1);
  canvas.write_png(path);
}

// A method's name as a file name: overrides "fast:leaf=4" become "fast_leaf-4".
std::string file_stem(std::string name) {
  for (char& c : name)
    if (c == ':') c = '_';
    else if (c == '=') c = '-';
  return name;
}

}  // namespace

RenderResult run_render(const Context& context, const SourceTree& tree, const RenderSetup& setup) {
  validate_render_setup(setup);
  create_output_directory(setup.out);
  const Scene scene = make_scene(find_scene_fixture(setup.scene), setup.map_size);
  const PcssPipeline pipeline(context, tree);
  const PcssInputs inputs = pipeline.render_inputs(scene, setup.screen_size);
  const int size = setup.screen_size;

  // The physical reference: the average of light_samples² point-light hard shadows.
  const PhysicalReferenceRenderer physical_renderer(context, tree);
  const Image physical = read_float_texture(
      context, physical_renderer.render(scene, size, setup.light_samples, setup.methods.front().bias), size, size, 1);
  const Image surface = read_float_texture(context, SurfaceRenderer(context, tree).render(scene, size), size, size, 4);

  std::vector<Image> shadows;
  RenderResult result;
  for (const PcssSettings& method : setup.methods) {
    const PcssMeasurement m = pipeline.measure(inputs, method, setup.repeats);
    shadows.push_back(read_float_texture(context, m.frame.soft_shadow(), size, size, 1));
    RenderRow row;
    row.method = method.name;
    row.gpu_ms = m.total_ms;
    row.representative_fraction = m.stats.representative_fraction();
    row.work_per_receiver = m.stats.work_per_receiver();
    row.stages = m.stage_ms;
    result.rows.push_back(row);
  }
  // SSIM against the first method that is exact PCSS, when one was rendered.
  int exact = -1;
  for (size_t i = 0; i < setup.methods.size() && exact < 0; ++i)
    if (setup.methods[i].name == exact_pcss().name) exact = static_cast<int>(i);

  const auto write = [&](const std::filesystem::path& path, auto writer, const Image& image) {
    writer(image, path);
    result.written.push_back(path);
  };
  const std::string prefix = setup.scene + "_";
  write(setup.out / (prefix + "physical_shadow.png"), write_grey, physical);
  const Image physical_lit = compose_lit_image(surface, physical);
  write(setup.out / (prefix + "physical_lit.png"), write_rgb, physical_lit);
  std::vector<Image> lit{physical_lit};
  for (size_t i = 0; i < shadows.size(); ++i) {
    lit.push_back(compose_lit_image(surface, shadows[i]));
    RenderRow& row = result.rows[i];
    row.ssim_exact = exact >= 0 ? ssim(shadows[exact], shadows[i]) : 0.0;
    row.ssim_physical = ssim(physical, shadows[i]);
    row.ssim_exact_lit = exact >= 0 ? lit_ssim(surface, shadows[exact], shadows[i]) : 0.0;
    const std::string stem = prefix + file_stem(setup.methods[i].name);
    write(setup.out / (stem + "_shadow.png"), write_grey, shadows[i]);
    write(setup.out / (stem + "_lit.png"), write_rgb, lit.back());
  }
  // The sheet: the physical reference, then every method, lit images above their soft-shadow maps.
  const int gap = 4;
  Canvas sheet(static_cast<int>(lit.size()) * (size + gap) - gap, 2 * size + gap, {255, 255, 255});
  for (size_t i = 0; i < lit.size(); ++i) {
    const int x = static_cast<int>(i) * (size + gap);
    sheet.rgb(flip_rows(lit[i]), x, 0, 1);
    sheet.grey(flip_rows(i == 0 ? physical : shadows[i - 1]), 0, x, size + gap, 1, 0.0f, 1.0f, {255, 0, 255});
  }
  const auto sheet_path = setup.out / (prefix + "sheet.png");
  sheet.write_png(sheet_path);
  result.written.push_back(sheet_path);
  return result;
}

void print_render_table(std::ostream& out, const RenderSetup& setup, const RenderResult& result, bool stages) {
  out << "sheet columns: physical reference";
  for (const RenderRow& r : result.rows) out << ", " << r.method;
  out << " (lit images above soft-shadow maps)\n";
  out << "scene " << setup.scene << ", shadow map " << setup.map_size << "x" << setup.map_size << ", screen "
      << setup.screen_size << "x" << setup.screen_size << ", median of " << setup.repeats << " runs\n";
  out << std::left << std::setw(20) << "method" << std::right << std::setw(12) << "GPU ms" << std::setw(12)
      << "SSIM exact" << std::setw(14) << "SSIM physical" << std::setw(10) << "lit SSIM" << std::setw(10) << "repr." << std::setw(12)
      << "work/px" << "\n";
  for (const RenderRow& r : result.rows)
    out << std::left << std::setw(20) << r.method << std::right << std::fixed << std::setprecision(2) << std::setw(12)
        << r.gpu_ms << std::setprecision(4) << std::setw(12) << r.ssim_exact << std::setw(14) << r.ssim_physical << std::setw(10) << r.ssim_exact_lit
        << std::setprecision(3) << std::setw(10) << r.representative_fraction << std::setprecision(1)
        << std::setw(12) << r.work_per_receiver << "\n";
  if (stages)
    for (const RenderRow& r : result.rows) {
      out << r.method << ":";
      for (const auto& [name, ms] : r.stages) out << "  " << name << " " << std::fixed << std::setprecision(2) << ms;
      out << "\n";
    }
  out.unsetf(std::ios::floatfield);
}

}  // namespace pn
