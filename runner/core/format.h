// printf-style formatting of one number, for messages and tables.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace pn {

// `spec` is a printf conversion for a double, e.g. "%g", "%.9g", "%.2e".
inline std::string format_number(const char* spec, double value) {
  char text[64];
  std::snprintf(text, sizeof text, spec, value);
  return text;
}

// The shortest decimal that reads back as `value` (issue 39 C21): a message about a bound never
// prints 0.09999999999999999 as "0.1", nor 1.0000000000000002 as "1".
inline std::string format_shortest(double value) {
  char text[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value || value != value) break;
  }
  return text;
}

// Milliseconds with two decimals, or "n/a" for NaN: a GPU time the context could not measure
// (no timer queries, gl/gpu_timer.h).
inline std::string format_ms(double ms) { return ms != ms ? "n/a" : format_number("%.2f", ms); }

}  // namespace pn
