// The benchmarks' line charts: nice tick steps, and a chart that draws its series where their values say.
#include <catch2/catch.hpp>

#include <cmath>

#include "draw/line_chart.h"

TEST_CASE("line charts: tick steps of 1, 2 or 5 times a power of ten, about the asked count") {
  CHECK(pn::nice_tick_step(10.0, 5) == 2.0);
  CHECK(pn::nice_tick_step(1.0, 5) == Approx(0.2));
  CHECK(pn::nice_tick_step(150.0, 6) == 50.0);
  CHECK(pn::nice_tick_step(7.0, 6) == 2.0);
  CHECK(pn::nice_tick_step(0.03, 3) == Approx(0.01));
}

TEST_CASE("line charts: a series' colour appears, one panel per panel, a NaN point left out") {
  const pn::Rgb red{200, 40, 40};
  pn::ChartPanel panel{"t", "x", "y", {{"a", red, false, {{0.0, 1.0}, {0.5, NAN}, {1.0, 2.0}}}}};
  const pn::Canvas one = pn::draw_line_charts("title", {panel});
  const pn::Canvas two = pn::draw_line_charts("title", {panel, panel});
  CHECK(two.width() > 2 * one.width() - 100);
  int reds = 0;
  for (int y = 0; y < one.height(); ++y)
    for (int x = 0; x < one.width(); ++x) reds += one.pixel(x, y) == red;
  CHECK(reds > 100);  // the line from (0, 1) to (1, 2), its markers and the legend's sample
}
