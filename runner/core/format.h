// printf-style formatting of one number, for messages and tables.
#pragma once

#include <cstdio>
#include <string>

namespace pn {

// `spec` is a printf conversion for a double, e.g. "%g", "%.9g", "%.2e".
inline std::string format_number(const char* spec, double value) {
  char text[64];
  std::snprintf(text, sizeof text, spec, value);
  return text;
}

// Milliseconds with two decimals, or "n/a" for NaN: a GPU time the context could not measure
// (no timer queries, gl/gpu_timer.h).
inline std::string format_ms(double ms) { return ms != ms ? "n/a" : format_number("%.2f", ms); }

}  // namespace pn
