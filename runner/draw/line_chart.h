// Line charts on a Canvas, for the benchmarks that plot themselves (`bench
// cache --plot`): panels side by side, each with its axes (the y axis from 0,
// ticks at 1, 2 or 5 times a power of ten), its series as lines with a
// marker at each point, and one legend for all.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "draw/canvas.h"

namespace pn {

struct ChartSeries {
  std::string label;
  Rgb colour;
  bool dashed = false;
  std::vector<std::pair<double, double>> points;  // (x, y) in order of x; non-finite y left out
  bool lines = true;  // false: markers only (a scatter)
  int marker = 7;     // side of each point's square, pixels
};

struct ChartPanel {
  std::string title, x_label, y_label;
  std::vector<ChartSeries> series;
  bool log_x = false;  // x on a log scale (x > 0; ticks at 1, 2, 5 × 10^k)
};

// `title` above the panels; the legend (every label once, in the order the panels first use it)
// below them. `columns`
// panels a row (0: all in one row).
Canvas draw_line_charts(const std::string& title, const std::vector<ChartPanel>& panels, int columns = 0);

// The step of about `count` nice ticks (1, 2 or 5 × 10^k) from 0 to `top` (> 0).
double nice_tick_step(double top, int count);

}  // namespace pn
