// Issue 51's picture: one penumbra of the boxes scene on a 128² map seen on a 512² screen, zoomed
// — the truth, Poisson PCSS, and exact PCSS, HQEPCSS and Fast PCSS over integer squares (the staircase and
// Fast PCSS's stipple: `edges=texel`, the form before issue 51) and over squares with area-weighted
// edges (PN_AREA_EDGES, the modules' default since: no steps).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "draw/font.h"
#include "figures/figures.h"
#include "metrics/lit_image.h"
#include "scene/scene.h"
#include "technique/comparison.h"
#include "technique/technique_registry.h"

namespace pn {
namespace {

// [x, x + w) × [y, y + h) of an image, rows counted from the top as the figure shows them.
Image crop_shown(const Image& image, int x, int y, int w, int h) {
  const Image shown = flip_rows(image);
  Image out(w, h, shown.channels);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < shown.channels; ++c) out.at(i, j, c) = shown.at(x + i, y + j, c);
  return out;
}

}  // namespace

Canvas area_edges_figure(const Context& context, const SourceTree& tree) {
  const int map = 128, screen = 512, scale = 2, gap = 8, label = 18;
  const int crop_x = 0, crop_y = 300, crop_w = 144, crop_h = 96;  // the front left boxes' shadows
  const Scene scene = make_scene(find_scene_fixture("boxes"), map);
  // Top row: the truth, then the integer squares; bottom row: Poisson, then the same calls with
  // area-weighted edges. Each panel: its caption and the technique (none: the truth).
  const std::vector<std::pair<std::string, std::string>> panels{
      {"truth (ray traced)", ""},
      {"exact PCSS, texel squares", "exact:stages=off:edges=texel"},
      {"HQEPCSS, texel squares", "hqepcss:edges=texel"},
      {"fast, texel squares", "fast:edges=texel"},
      {"Poisson 36/64", "poisson"},
      {"exact PCSS, area-weighted edges", "exact:stages=off"},
      {"HQEPCSS, area-weighted edges", "hqepcss"},
      {"fast, area-weighted edges", "fast"}};
  std::vector<std::unique_ptr<TechniqueConfig>> configs;
  ComparisonSetup setup;
  setup.screen_size = screen, setup.repeats = 1, setup.truth_samples = 8;
  for (const auto& [caption, technique] : panels) {
    if (technique.empty()) continue;
    configs.push_back(parse_technique(technique));
    setup.techniques.push_back(configs.back().get());
  }
  const Comparison c = compare_techniques(context, tree, scene, setup);
  const Font font;
  const Rgb ink{40, 40, 40};
  const int panel_w = crop_w * scale, panel_h = crop_h * scale, columns = 4;
  Canvas canvas(columns * (panel_w + gap) + gap, 2 * (panel_h + label + gap) + gap, {255, 255, 255});
  size_t result = 0;
  for (size_t i = 0; i < panels.size(); ++i) {
    const int x = gap + static_cast<int>(i % columns) * (panel_w + gap);
    const int y = gap + static_cast<int>(i / columns) * (panel_h + label + gap);
    const Image& visibility = panels[i].second.empty() ? c.truth : c.results[result++].visibility;
    canvas.text(font, x, y, panels[i].first, 13, ink);
    canvas.rgb(crop_shown(compose_lit_image(c.surface, visibility), crop_x, crop_y, crop_w, crop_h), x, y + label,
               scale);
  }
  return canvas;
}

}  // namespace pn
