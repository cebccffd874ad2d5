// CPU definition of glsl/savsm.glsl (summed-area variance soft shadows),
// written from its definition in double and never through a table: the mean
// and variance of a rectangle's depths are summed texel by texel (two-pass),
// and every step — the search square, the Chebyshev blocker estimate or the
// square's min, Eq. (1)'s filter square, the Chebyshev bound, the bleeding
// reduction and the depth-range bound — follows the module's header in double.
#pragma once

#include "core/image.h"
#include "core/texel_rect.h"
#include "modules/savsm_face.h"
#include "reference/vsm_reference.h"        // DepthRange, chebyshev, reduce_bleeding
#include "scene/light_model.h"

namespace pn {

// Mean and variance (depth units) of a rectangle's texels, each clamped to [near, far] and read
// as far where not finite (the table's unit depth, undone); texels 0: mean and variance 0.
struct SavsmMoments {
  double mean = 0.0, variance = 0.0;
  long texels = 0;
};
SavsmMoments savsm_rect_moments(const Image& depth, const Rect& rect, double near_depth, double far_depth);

// The TABLE mode's blocker depth from a square's moments at t = dP - bias: p = Chebyshev(mu, v, t)
// (v the variance floored by min_variance mu^2, as vsm.glsl); no blocker when p >= 1 -
// kSavsmMinOccluded; else z = mu - v / (t - mu) (= (mu - p t) / (1 - p)) clamped to [near, t].
struct SavsmBlockerEstimate {
  bool has = false;
  double depth = 0.0;
};
SavsmBlockerEstimate savsm_blocker_from_moments(double mean, double variance, double t, double min_variance,
                                                double near_depth);

// Min and max of the sanitized depths (non-finite: +Inf) over the aligned nodes of the min/max
// mip chain that cover the rectangle's square (mip_square_cover): the superset the module reads.
DepthRange savsm_square_range(const Image& depth, const Rect& rect);

// The module's result for one receiver, in double. `search` / `filter`, when given, replace the
// squares the reference would compute (the check feeds the module's own where a rounding of a
// side or an origin sits within float's reach of flipping).
struct SavsmEstimate {
  bool surface = false;  // a finite receiver whose search square meets the map
  Rect search, filter;
  bool lit_by_bound = false;  // t <= the search square's min (bound on)
  bool has_blocker = false;
  double blocker = 0.0, filter_side = 0.0;
  SavsmMoments filter_moments;
  double chebyshev = 1.0, reduced = 1.0, bound = PN_VSM_BOUND_NONE, visibility = 1.0;
};
SavsmEstimate savsm_reference(const Image& depth, const LightModel& light, const SavsmReceiver& receiver,
                              const SavsmSettings& settings, const Rect* search = nullptr,
                              const Rect* filter = nullptr);

// The exact PCF visibility over a rectangle for the float threshold t: 1 − pcf_reference's
// occluded fraction (a texel occludes when finite and below t); 1 for an empty rectangle.
double savsm_pcf_visibility(const Image& depth, const Rect& rect, float t);

// The texel fetches the module makes for a receiver whose path the estimate describes, on an
// n×n map: 4 a table rectangle, one a mip node covering a square (mip_square_cover's nodes, at
// most 9) — at most 26, whatever the widths.
int savsm_square_fetches(const Rect& rect, int n);
int savsm_fetches(const SavsmEstimate& e, const SavsmSettings& settings, int n);

}  // namespace pn
