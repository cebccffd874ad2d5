// Cases of the cascades check: glsl/cascades.h and cascades.glsl through
// passes/cascades_query.comp against reference/cascades_reference (the
// definitions in double), and the runner's cascade fit (cascades/cascade_fit,
// the same formulas in float) for the properties a stable cascade promises.
//
// Tolerances, u = 2^-24:
// - splits: GLSL's pow is exp2(t log2(f/n)) with log2 within 3 ulp and exp2
//   within 3 + 2|x| ulp (GLSL 4.50 §4.7.1); for f/n <= 10^4 (|x| <= 13.3)
//   that is < 60 ulp of the power, plus a few roundings of Eq. 7's two
//   positive terms (no cancellation): relative 128 u. The hybrid split is a
//   minimum of such values times factors (a few more roundings): the same
//   bound. The endpoints C_0 = n and C_m = f are exact.
// - adaptive lambda: 0.4 · 0.301 · log2(f/n)'s error (3 ulp of <= 14): absolute 2^-18.
// - enlargement: (k - 1) / 2^(i - 1) + 1, two roundings: relative 4 u.
// - selection: index and next exact (the same float splits on both sides);
//   the weight's error is the band start's rounding over the band's width
//   plus the division's: absolute 4 u f / (narrowest band) + 8 u, printed per case.
//   Continuity across each split (band > 0): the blended visibility just
//   below a split and at it differ by < 1e-4.
// - slice sphere: centre and radius relative 32 u against a ternary search over
//   the on-axis centre (300 steps, converged far below float rounding); every
//   corner within the GPU's radius (1 + 32 u).
// - snap: floor(x / t + 0.5) exact, leaving out queries within 8 u (|x / t| + 1)
//   of a rounding boundary (GLSL's division is within 2.5 ulp); the number left
//   out is printed and must stay below 1 %.
// - stability (CPU, the runner's fit): along a camera path of sub-texel moves
//   and small turns, a world point's map position changes by whole texels
//   within 0.01 texel (float matrices), and the radius not at all; the unstable
//   fit must show a fractional change of at least 0.05 texel (the measure can
//   tell them apart). Every corner of each cascade's fitted slice lies inside
//   its map (within 0.001 texel) and before its depth range's far end, for both fits.
#include "check/cascades_cases.h"
#include "check/row_image.h"

namespace pn {

CaseResult row_case(const std::string& name, const std::vector<float>& expected, const std::vector<float>& observed,
                    const Tolerance& tolerance) {
  return {name, tolerance, compare(row_image(expected), row_image(observed), tolerance)};
}

std::vector<CaseResult> run_cascades_check(const CheckEnvironment& env) {
  const CascadesQueryPass gpu(env.device, env.tree);
  std::vector<CaseResult> results;
  split_cases(gpu, results);
  selection_cases(gpu, results);
  sphere_cases(gpu, results);
  blend_pass_cases(env, results);
  city_cases(env, results);
  stability_cases(results);
  return results;
}

}  // namespace pn
