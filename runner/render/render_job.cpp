#include "render/render_job.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iomanip>

#include "core/content_hash.h"
#include "core/error.h"
#include "core/format.h"
#include "core/named.h"
#include "core/write_file.h"
#include "draw/canvas.h"
#include "draw/font.h"
#include "metrics/lit_image.h"
#include "cascades/cascade_math.h"
#include "scene/city_scene.h"
#include "scene/model.h"
#include "scene/scene.h"
#include "technique/shadow_map_sources.h"
#include "technique/technique_registry.h"

namespace pn {

namespace {

constexpr float kErrorLimit = 0.5f;  // the error pictures saturate at ±0.5 visibility

// Writes `canvas` to `path`; returns the hash of the bytes written.
std::string write_canvas(const Canvas& canvas, const std::filesystem::path& path) {
  const std::string bytes = canvas.png();
  write_file_atomically(path, bytes);
  return content_hash(bytes);
}

std::string write_grey(const Image& image, const std::filesystem::path& path) {
  Canvas canvas(image.width, image.height, {0, 0, 0});
  canvas.grey(flip_rows(image), 0, 0, 0, 1, 0.0f, 1.0f, {255, 0, 255});
  return write_canvas(canvas, path);
}

std::string write_rgb(const Image& image, const std::filesystem::path& path) {
  Canvas canvas(image.width, image.height, {0, 0, 0});
  canvas.rgb(flip_rows(image), 0, 0, 1);
  return write_canvas(canvas, path);
}

// The error picture with its scale at its right (issue 26 B19: a picture read on its own says
// what its colours mean): the signed map's bar from +limit to -limit, labelled.
std::string write_signed(const Image& image, const std::filesystem::path& path) {
  const Font font;
  const int text = std::clamp(image.height / 20, 10, 16), bar = 12, margin = 6;
  const int label = font.text_width("\u2212" + format_number("%g", kErrorLimit), text);
  Canvas canvas(image.width + margin + bar + 4 + label + margin, image.height, {255, 255, 255});
  canvas.signed_map(flip_rows(image), 0, 0, 0, 1, kErrorLimit);
  canvas.colour_bar(font, image.width + margin, margin, bar, image.height - 2 * margin, kErrorLimit, text, {0, 0, 0});
  return write_canvas(canvas, path);
}

Image difference(const Image& observed, const Image& reference) {
  Image out = observed;
  for (size_t i = 0; i < out.texels.size(); ++i) out.texels[i] -= reference.texels[i];
  return out;
}

// A technique's name as a file name: overrides "fast:leaf=4" become "fast_leaf-4".
std::string file_stem(std::string name) {
  for (char& c : name)
    if (c == ':') c = '_';
    else if (c == '=') c = '-';
  return name;
}

std::string score_label(const char* what, const std::optional<Scores>& s) {
  if (!s) return std::string(what) + " -";
  char text[96];
  std::snprintf(text, sizeof text, "%s %.3f / %.3f", what, s->light_facing.ssim, s->light_facing.mae);
  return text;
}

// The sheet: a column per picture (the truth, then every technique), rows lit
// image, soft-shadow map and signed error against the truth, each column
// headed by its name and its light-facing SSIM / MAE against the truth and
// exact PCSS.
Canvas draw_sheet(const std::string& title, const Comparison& c) {
  const Font font;
  const int size = c.truth.width, gap = 6, text = 13, line = text + 3;
  const int label_width = 104, header = 3 * line + 4, title_height = line + 6;
  const int column = std::max(size, 190);
  const int columns = 1 + static_cast<int>(c.results.size());
  Canvas sheet(label_width + columns * (column + gap), title_height + header + 3 * (size + gap), {255, 255, 255});
  const Rgb ink{20, 20, 20};
  sheet.text(font, 4, 3, title, text, ink);
  const int top = title_height + header;
  const char* rows[] = {"lit", "soft shadow", "error vs truth"};
  for (int r = 0; r < 3; ++r) sheet.text(font, 4, top + r * (size + gap) + size / 2 - text / 2, rows[r], text, ink);
  for (int i = 0; i < columns; ++i) {
    const int x = label_width + i * (column + gap), y = title_height;
    const TechniqueResult* r = i == 0 ? nullptr : &c.results[static_cast<size_t>(i - 1)];
    const Image& visibility = r ? r->visibility : c.truth;
    sheet.text(font, x, y, r ? r->name : "truth (ray traced)", text, ink);
    sheet.text(font, x, y + line, r ? score_label("truth", r->vs_truth) : "the reference of the scores", text - 2, ink);
    sheet.text(font, x, y + 2 * line, score_label("exact", r ? r->vs_exact : c.truth_vs_exact), text - 2, ink);
    sheet.rgb(flip_rows(compose_lit_image(c.surface, visibility)), x, top, 1);
    sheet.grey(flip_rows(visibility), 0, x, top + size + gap, 1, 0.0f, 1.0f, {255, 0, 255});
    if (r) sheet.signed_map(flip_rows(difference(r->visibility, c.truth)), 0, x, top + 2 * (size + gap), 1, kErrorLimit);
    else sheet.colour_bar(font, x, top + 2 * (size + gap), 12, size, kErrorLimit, text - 2, ink);
  }
  return sheet;
}

// The scene fixture kinds render knows, by name: throws Error listing every name.
void validate_scene_name(const std::string& name) {
  if (find_city_scene_fixture_or_null(name) || find_named_or_null(fixtures::kScenes, name)) return;
  throw Error("unknown scene '" + name + "': expected one of " + known_names(fixtures::kScenes) + ", " +
              known_names(fixtures::kCityScenes));
}

// The lit image with each pixel tinted by its cascade's colour (none: untinted).
Image cascade_overlay(const Image& lit, const Image& cascade_index) {
  static const float tints[4][3] = {{1.0f, 0.35f, 0.3f}, {0.35f, 0.9f, 0.35f}, {0.35f, 0.5f, 1.0f}, {1.0f, 0.85f, 0.25f}};
  Image out = lit;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const int c = static_cast<int>(cascade_index.at(x, y));
      if (c < 0 || c > 3) continue;
      for (int k = 0; k < 3; ++k) out.at(x, y, k) = 0.6f * out.at(x, y, k) + 0.4f * tints[c][k];
    }
  return out;
}

}  // namespace

void validate_render_setup(const RenderSetup& s) {
  if (s.model.empty()) validate_scene_name(s.scene);
  if (s.cascades < 0 || s.cascades > PN_CASCADES_MAX)
    throw Error("cascades " + std::to_string(s.cascades) + ": expected 0 (one map over the scene) .. " +
                std::to_string(PN_CASCADES_MAX));
  find_shadow_map_source(s.source);
  validate_light_width_factor(s.light_scale, "light scale");
  if (s.map_size < 16 || s.map_size > 4096) throw Error("shadow-map size " + std::to_string(s.map_size) + ": expected 16..4096");
  if (s.screen_size < 16 || s.screen_size > 4096) throw Error("screen size " + std::to_string(s.screen_size) + ": expected 16..4096");
  if (s.truth_samples < 1 || s.truth_samples > 64) throw Error("truth samples " + std::to_string(s.truth_samples) + ": expected 1..64 per side");
  if (s.repeats < 1 || s.repeats > 100) throw Error("repeats " + std::to_string(s.repeats) + ": expected 1..100");
  for (const auto& m : s.techniques) m->validate();
}

Scene load_render_scene(const RenderSetup& s) {
  const fixtures::CitySceneFixture* city = s.model.empty() ? find_city_scene_fixture_or_null(s.scene) : nullptr;
  Scene scene = city ? make_city_scene(*city, s.map_size)
                     : s.model.empty() ? make_scene(find_scene_fixture(s.scene), s.map_size)
                                       : make_model_scene(s.model, s.map_size);
  scale_light_width(scene, s.light_scale, "light scale");
  return scene;
}

void create_output_directory(const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw Error("output directory '" + out.string() + "': cannot be created (" + ec.message() + ")");
}

namespace {

// A render's file for `stem`: "<scene>_<stem>.png" (the manifest: ".txt").
std::string render_file_name(const std::string& scene, const std::string& stem, const char* extension = ".png") {
  return scene + "_" + stem + extension;
}

}  // namespace

std::vector<std::string> render_output_names(const RenderSetup& setup, const Scene& scene) {
  std::vector<std::unique_ptr<TechniqueConfig>> own;
  std::vector<std::string> names{render_file_name(scene.name, "truth_shadow"), render_file_name(scene.name, "truth_lit")};
  const bool cascaded = scene.sun && setup.cascades > 0;
  for (const TechniqueConfig* t : chosen_or_default_techniques(setup.techniques, render_techniques(), own)) {
    const std::string stem = file_stem(t->name());
    for (const char* kind : {"_shadow", "_lit", "_error"}) names.push_back(render_file_name(scene.name, stem + kind));
    if (cascaded) names.push_back(render_file_name(scene.name, stem + "_cascades"));
  }
  names.push_back(render_file_name(scene.name, "sheet"));
  names.push_back(render_file_name(scene.name, "manifest", ".txt"));
  return names;
}

RenderResult run_render(const Context& context, const SourceTree& tree, const RenderSetup& setup, const Scene& scene) {
  validate_render_setup(setup);
  std::vector<std::unique_ptr<TechniqueConfig>> own;
  ComparisonSetup cs;
  cs.source = setup.source;
  cs.screen_size = setup.screen_size;
  cs.repeats = setup.repeats;
  cs.truth_samples = setup.truth_samples;
  if (setup.cascades > 0) {
    CascadeSettings cascades;
    cascades.count = setup.cascades;
    cascades.map_size = setup.map_size;
    cs.cascades = cascades;
  }
  cs.techniques = chosen_or_default_techniques(setup.techniques, render_techniques(), own);
  RenderResult result;
  result.scene_name = scene.name;
  result.comparison = compare_techniques(context, tree, scene, cs);
  const Comparison& c = result.comparison;

  create_output_directory(setup.out);
  // The set is complete when its manifest is there (written last): the previous run's goes first,
  // so a run that stops half-way (an error, a signal) leaves new files and no manifest.
  const auto manifest_path = setup.out / render_file_name(scene.name, "manifest", ".txt");
  std::error_code ec;
  std::filesystem::remove(manifest_path, ec);
  if (ec) throw Error("output '" + manifest_path.string() + "': cannot be removed (" + ec.message() + ")");
  // The hash of each file as this run wrote it: another run writing into the same --out between
  // this run's files and its manifest (issue 39 C10) leaves files whose bytes the manifest disowns.
  std::vector<std::string> hashes;
  const auto write = [&](const std::string& stem, auto writer, const Image& image) {
    const auto path = setup.out / render_file_name(scene.name, stem);
    hashes.push_back(writer(image, path));
    result.written.push_back(path);
  };
  write("truth_shadow", write_grey, c.truth);
  write("truth_lit", write_rgb, compose_lit_image(c.surface, c.truth));
  for (const TechniqueResult& r : c.results) {
    const std::string stem = file_stem(r.name);
    write(stem + "_shadow", write_grey, r.visibility);
    write(stem + "_lit", write_rgb, compose_lit_image(c.surface, r.visibility));
    write(stem + "_error", write_signed, difference(r.visibility, c.truth));
    if (c.cascade_index) write(stem + "_cascades", write_rgb, cascade_overlay(compose_lit_image(c.surface, r.visibility), *c.cascade_index));
  }
  const std::string light = setup.light_scale == 1.0 ? "" : ", light width ×" + format_number("%g", setup.light_scale);
  const std::string maps = c.cascades.empty() ? "shadow map " : std::to_string(c.cascades.size()) + " cascades of ";
  const std::string title = "scene " + scene.name + light + ", " + maps + std::to_string(setup.map_size) + "², screen " +
                            std::to_string(setup.screen_size) + "², truth " + std::to_string(setup.truth_samples) +
                            "×" + std::to_string(setup.truth_samples) +
                            " light samples; scores on light-facing pixels: SSIM / MAE";
  const auto sheet_path = setup.out / render_file_name(scene.name, "sheet");
  hashes.push_back(write_canvas(draw_sheet(title, c), sheet_path));
  result.written.push_back(sheet_path);
  std::string manifest;  // `HASH  NAME` a file, as sha256sum lays it out (FNV-1a 64)
  for (size_t i = 0; i < result.written.size(); ++i)
    manifest += hashes[i] + "  " + result.written[i].filename().string() + "\n";
  write_file_atomically(manifest_path, manifest);
  result.written.push_back(manifest_path);
  return result;
}

void print_render_table(std::ostream& out, const RenderSetup& setup, const RenderResult& result, bool stages) {
  out << "scene " << result.scene_name;
  if (setup.light_scale != 1.0) out << ", light width x" << format_number("%g", setup.light_scale);
  const size_t cascades = result.comparison.cascades.size();
  out << ", " << (cascades > 0 ? std::to_string(cascades) + " cascades of " : "shadow map ") << setup.map_size << "x"
      << setup.map_size << " (source " << setup.source << ", " << format_ms(result.comparison.shadow_map_ms) << " ms"
      << (result.comparison.second_layer_ms > 0.0
              ? ", second layers " + format_ms(result.comparison.second_layer_ms) + " ms"
              : std::string())
      << "), screen " << setup.screen_size << "x" << setup.screen_size << ", median of " << setup.repeats
      << " runs, truth " << setup.truth_samples << "x" << setup.truth_samples << " light samples\n";
  out.unsetf(std::ios::floatfield);
  print_score_tables(out, result.comparison);
  if (stages)
    for (const TechniqueResult& r : result.comparison.results) {
      out << r.name << ":";
      for (const auto& [name, ms] : r.measurement.stage_ms) out << "  " << name << " " << format_ms(ms);
      out << "\n";
    }
  out.unsetf(std::ios::floatfield);
}

}  // namespace pn
