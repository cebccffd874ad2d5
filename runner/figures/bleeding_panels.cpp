#include "figures/bleeding_panels.h"

#include "draw/font.h"

namespace pn {

Canvas bleeding_panels(const Image& map, const Image& exact, const std::string& exact_name,
                       const std::vector<BleedingPanel>& panels) {
  const int n = map.width, scale = 3, gap = 10, label = 18, panel = n * scale;
  const int shown = static_cast<int>(panels.size());
  bool footers = false;
  for (const BleedingPanel& p : panels) footers = footers || !p.footer.empty();
  const Font font;
  const Rgb ink{40, 40, 40};
  Canvas canvas((2 + shown) * panel + (3 + shown) * gap + 60, 2 * (panel + label) + 3 * gap + (footers ? label : 0),
                {255, 255, 255});
  canvas.text(font, gap, gap, "depth map", 13, ink);
  canvas.grey(map, 0, gap, gap + label, scale, 0.0f, 1.0f, {220, 0, 180});
  canvas.text(font, 2 * gap + panel, gap, exact_name, 13, ink);
  canvas.grey(exact, 0, 2 * gap + panel, gap + label, scale, 0.0f, 1.0f, {220, 0, 180});
  for (int i = 0; i < shown; ++i) {
    const BleedingPanel& p = panels[static_cast<size_t>(i)];
    const int x = (3 + i) * gap + (2 + i) * panel;
    canvas.text(font, x, gap, p.name, 13, ink);
    canvas.grey(p.visibility, 0, x, gap + label, scale, 0.0f, 1.0f, {220, 0, 180});
    Image error(n, n);
    for (size_t k = 0; k < error.texels.size(); ++k) error.texels[k] = p.visibility.texels[k] - exact.texels[k];
    canvas.signed_map(error, 0, x, 2 * gap + panel + 2 * label, scale, 0.25f);
    if (!p.footer.empty()) canvas.text(font, x, 3 * gap + 2 * panel + 2 * label, p.footer, 13, ink);
  }
  canvas.text(font, 2 * gap + panel, 2 * gap + panel + label, "error vs exact PCF (red: bleeding)", 13, ink);
  canvas.colour_bar(font, (2 + shown) * panel + (3 + shown) * gap, 2 * gap + panel + 2 * label, 12, panel, 0.25f, 11,
                    ink);
  return canvas;
}

}  // namespace pn
