#include "draw/line_chart.h"

#include <algorithm>
#include <cmath>

#include "core/format.h"

namespace pn {

double nice_tick_step(double top, int count) {
  const double raw = top / std::max(count, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

Canvas draw_line_charts(const std::string& title, const std::vector<ChartPanel>& panels, int columns) {
  const Font font;
  const Rgb ink{20, 20, 20}, grid{225, 225, 225};
  const int text = 13, panel_w = 460, panel_h = 330, left = 62, right = 16, top = 62, bottom = 44, gap = 24;
  // The legend: every label once, in the order the panels first use it.
  std::vector<const ChartSeries*> legend;
  for (const ChartPanel& panel : panels)
    for (const ChartSeries& s : panel.series)
      if (std::none_of(legend.begin(), legend.end(), [&](const ChartSeries* l) { return l->label == s.label; }))
        legend.push_back(&s);
  const size_t legend_items = legend.size();
  const int legend_rows = static_cast<int>((legend_items + 2) / 3);
  const int count = static_cast<int>(panels.size());
  const int per_row = columns > 0 ? std::min(columns, std::max(count, 1)) : std::max(count, 1);
  const int rows = (count + per_row - 1) / per_row;
  const int row_h = top + panel_h + bottom;
  const int width = per_row * (left + panel_w + right) + (per_row - 1) * gap;
  Canvas canvas(std::max(width, 200), std::max(rows, 1) * row_h + 12 + legend_rows * (text + 8), {255, 255, 255});
  canvas.text(font, 8, 6, title, text, ink);

  for (size_t p = 0; p < panels.size(); ++p) {
    const ChartPanel& panel = panels[p];
    const int column = static_cast<int>(p) % per_row, row = static_cast<int>(p) / per_row;
    const int ox = column * (left + panel_w + right + gap) + left, oy = top + row * row_h;
    const auto axis_x = [&](double x) { return panel.log_x ? std::log10(x) : x; };
    double x_lo = INFINITY, x_hi = -INFINITY, y_hi = 0.0;
    for (const ChartSeries& s : panel.series)
      for (const auto& [x, y] : s.points)
        if (std::isfinite(y) && std::isfinite(axis_x(x)))
          x_lo = std::min(x_lo, axis_x(x)), x_hi = std::max(x_hi, axis_x(x)), y_hi = std::max(y_hi, y);
    if (panel.log_x && x_hi > x_lo) x_lo -= 0.03 * (x_hi - x_lo), x_hi += 0.03 * (x_hi - x_lo);
    if (!(x_hi > x_lo)) x_lo = 0.0, x_hi = 1.0;
    if (!(y_hi > 0.0)) y_hi = 1.0;
    const double y_step = nice_tick_step(y_hi * 1.05, 6);
    const double y_top = std::ceil(y_hi * 1.05 / y_step) * y_step;
    const auto px = [&](double x) { return ox + (axis_x(x) - x_lo) / (x_hi - x_lo) * panel_w; };
    const auto py = [&](double y) { return oy + panel_h - y / y_top * panel_h; };
    canvas.text(font, ox, oy - 2 * text - 4, panel.title, text, ink);
    for (double y = 0.0; y <= y_top + 1e-9; y += y_step) {
      canvas.line(ox, py(y), ox + panel_w, py(y), grid, 1);
      const std::string label = format_number("%g", y);
      canvas.text(font, ox - 6 - font.text_width(label, text - 2), static_cast<int>(py(y)) - text / 2, label, text - 2, ink);
    }
    std::vector<double> ticks;
    if (panel.log_x) {  // 1, 2, 5 × 10^k inside the range
      for (double decade = std::pow(10.0, std::floor(x_lo)); std::log10(decade) <= x_hi; decade *= 10.0)
        for (double m : {1.0, 2.0, 5.0})
          if (std::log10(m * decade) >= x_lo && std::log10(m * decade) <= x_hi) ticks.push_back(m * decade);
    } else {
      const double x_step = nice_tick_step(x_hi - x_lo, 5);
      for (double x = std::ceil(x_lo / x_step) * x_step; x <= x_hi + 1e-9; x += x_step) ticks.push_back(x);
    }
    for (double x : ticks) {
      canvas.line(px(x), oy, px(x), oy + panel_h, grid, 1);
      const std::string label = format_number("%g", x);
      canvas.text(font, static_cast<int>(px(x)) - font.text_width(label, text - 2) / 2, oy + panel_h + 4, label, text - 2, ink);
    }
    canvas.outline(ox, oy, panel_w + 1, panel_h + 1, ink);
    canvas.text(font, ox + panel_w / 2 - font.text_width(panel.x_label, text) / 2, oy + panel_h + 20, panel.x_label, text, ink);
    canvas.text(font, ox, oy - text - 2, panel.y_label, text - 2, ink);
    for (const ChartSeries& s : panel.series) {
      const std::pair<double, double>* last = nullptr;
      for (const auto& point : s.points) {
        if (!std::isfinite(point.second) || !std::isfinite(axis_x(point.first))) continue;
        if (last && s.lines)
          canvas.line(px(last->first), py(last->second), px(point.first), py(point.second), s.colour, 2, s.dashed ? 6 : 0);
        canvas.fill(static_cast<int>(px(point.first)) - s.marker / 2, static_cast<int>(py(point.second)) - s.marker / 2,
                    s.marker, s.marker, s.colour);
        last = &point;
      }
    }
  }
  // The legend.
  const int ly = std::max(rows, 1) * row_h + 6;
  for (size_t i = 0; i < legend_items; ++i) {
    const ChartSeries& s = *legend[i];
    const int x = left + static_cast<int>(i % 3) * 300, y = ly + static_cast<int>(i / 3) * (text + 8);
    canvas.line(x, y + text / 2, x + 30, y + text / 2, s.colour, 2, s.dashed ? 6 : 0);
    canvas.text(font, x + 38, y, s.label, text - 1, ink);
  }
  return canvas;
}

}  // namespace pn
