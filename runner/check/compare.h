// Comparison of a GPU result with its CPU reference under a stated tolerance,
// reporting the worst element as where / expected / observed (piglit style).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/image.h"

namespace pn {

struct Tolerance {
  enum class Kind { absolute, relative, rmse };
  Kind kind = Kind::absolute;
  double bound = 0.0;  // 0 means bit-exact for absolute

  static Tolerance exact() { return {Kind::absolute, 0.0}; }
  static Tolerance absolute(double b) { return {Kind::absolute, b}; }
  static Tolerance relative(double b) { return {Kind::relative, b}; }
  static Tolerance rmse(double b) { return {Kind::rmse, b}; }
  std::string describe() const;  // "abs <= 1.2e-05", "exact", ...
};

struct Comparison {
  bool pass = false;
  double worst_error = 0.0;  // in the tolerance's measure (abs, rel); RMSE for rmse
  double rmse = 0.0;
  int x = -1, y = -1, channel = 0;  // worst element (-1: none, e.g. a size mismatch)
  float expected = 0.0f;
  float observed = 0.0f;
  std::string problem;  // set when the images cannot be compared at all

  // "at (x, y)[c]: expected E, observed O (abs error 3.1e-04 > abs <= 1.0e-05)"
  std::string where(const Tolerance& tolerance) const;
};

// Element error: 0 when both are the same non-finite value (NaN and NaN, or
// the same infinity); infinite when only one is non-finite. Relative errors
// divide by max(|expected|, FLT_MIN).
Comparison compare(const Image& expected, const Image& observed, const Tolerance& tolerance);

// Elements that each carry their own bound: |observed − expected| <= bound (an interval [lo, hi]
// is its midpoint and half-width). A non-finite observed value fails. `where` places each element
// (x, y, channel) for the report.
struct BoundedElements {
  std::vector<double> expected, bounds;
  std::vector<float> observed;
  std::vector<std::array<int, 3>> where;
  void add(double e, float o, double bound, int x, int y, int channel = 0);
  void add_interval(double lo, double hi, float o, int x, int y, int channel = 0);
};

// The worst element is the one closest to (or furthest beyond) its bound; the tolerance returned
// is that element's bound.
Comparison compare_bounded(const BoundedElements& elements, Tolerance& tolerance);

}  // namespace pn
