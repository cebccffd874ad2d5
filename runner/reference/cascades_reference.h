// The cascades' formulas from their definitions, in double (docs/modules/cascades.md),
// written apart from glsl/cascades.h: the hybrid split as the closed-form minimum over
// the later splits (the module runs a recurrence), the slice's sphere as the smallest
// on-axis sphere around its eight corners found by search (the module has a closed form),
// the selection by scanning the split list.
#pragma once

#include <vector>

namespace pn {

// Eq. 7: C_i = lambda n (f/n)^(i/m) + (1 - lambda)(n + (f - n) i/m).
double practical_split_reference(double lambda, double near, double far, int i, int count);

// lambda = 0.6 + 0.4 clamp(log10(f/n) - 2, 0, 1).
double adaptive_lambda_reference(double near, double far);

// k_i = 1 + (max(k, 1) - 1) / 2^(i - 1).
double enlargement_reference(double k, int i);

// C'_0 ... C'_m: E_i = n + (C_i - n) k_i (0 < i < m), E_m = f, and
// C'_i = n + min_{j = i..m} (1 - g)^(j - i) (E_j - n).
std::vector<double> hybrid_splits_reference(double lambda, double near, double far, int count, double k, double gap);

// The receiver's cascade and the next cascade's weight for view depth z, splits
// split_far = C_1 ... C_m (C_0 = near), from the definitions of docs/modules/cascades.md.
struct CascadeChoiceReference {
  int index = 0, next = 0;
  double weight = 0;
};
CascadeChoiceReference cascade_choice_reference(double z, double near, const std::vector<double>& split_far,
                                                double band, bool fade_last);

// The smallest sphere centred on the view axis that holds the eight corners
// (+-a tanX, +-a tanY, a), (+-b tanX, +-b tanY, b): its centre depth and radius,
// by ternary search of the (convex) largest corner distance over the centre.
struct SphereReference {
  double centre = 0, radius = 0;
};
SphereReference slice_sphere_reference(double a, double b, double tan_x, double tan_y);

// The largest distance from (0, 0, centre) to the eight corners.
double farthest_corner_distance(double a, double b, double tan_x, double tan_y, double centre);

}  // namespace pn
