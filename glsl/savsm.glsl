// savsm.glsl — summed-area variance soft shadows (SAVSM): PCSS whose blocker
// search and filter read the mean and variance of the depths over any
// rectangle from a summed-area table of the moments, in a bounded number of
// fetches whatever the penumbra's width.
//
// description:
//   Seed 004's subject (Lauritzen, "Summed-Area Variance Shadow Maps", GPU
//   Gems 3 ch. 8) on SPEC §4.7's light model. For a receiver at shadow-map
//   texel position (u, v) and linear light depth dP, t = dP - bias:
//   1. Search square S: PCSS's blocker-search width for dP (blockers as near
//      as the near plane, light_model.glsl), as exact PCSS's square
//      (pnRegionSquare). With the bound on, the min over S from the aligned
//      min/max mip chain (minmax_mip.glsl: the nodes covering S, <= 9
//      fetches) decides "lit" exactly: t <= min -> visibility 1.
//   2. Blocker depth z (PN_SAVSM_BLOCKER_*, savsm.h):
//      TABLE — mean mu and variance s2 of S from the moments table
//              (4 fetches); the unoccluded share is at most
//              p = Chebyshev(mu, s2, t) (variance_bound.glsl, minimum variance), and,
//              taking the unoccluded texels at depth t,
//                mu = p t + (1 - p) z   ->   z = (mu - p t) / (1 - p)
//                                                = mu - s2 / (t - mu)
//              (the second form, free of 1 - p's cancellation, is what the
//              module computes), clamped to [near, t];
//              p >= 1 - PN_SAVSM_MIN_OCCLUDED: no blocker, lit.
//      MIN   — z = the min depth over the mip nodes covering S (the one read
//              for the lit test): the nearest blocker, the widest penumbra
//              the square allows.
//   3. Penumbra by Eq. (1) in texels at the receiver (light_model.glsl):
//      filter side w = c · penumbra, filter square F = pnRegionSquare(u, v, w).
//   4. Visibility: mean and variance of F from the table (4 fetches), the
//      one-sided Chebyshev bound p = s2 / (s2 + (t - mu)^2) for t > mu
//      (1 otherwise; vsm.glsl's minimum variance, relative to mu^2), the
//      light-bleeding reduction linstep(a, 1, p) and, with the bound on, the
//      depth-range bound over F from the mip chain (t <= min -> 1,
//      t > max -> 0; the nodes covering F are a superset of it, so each
//      decision is still right).
//   Depths enter the table as x = (d - near) / (far - near) clamped to [0, 1]
//   (non-finite: the far plane); mean and variance come back in depth units.
//   The bound reads the mip chain rather than the decreased depth pyramid:
//   the pyramid holds every window origin at every level (128 ms to build at
//   512² on llvmpipe against 3.6 ms for the chain) and its exact squares are
//   not needed for a bound.
//   A receiver without a surface, a non-finite depth, or a square that
//   misses the map is lit.
//
// use:
//   float pnSavsm(PN_SAVSM_TABLE_SAMPLER table, sampler2D mip, PnLight light, vec3 receiver,
//                 vec2 unitRange, PnSavsmSettings settings)     the call: the visibility of one receiver
//   PnSavsm pnSavsmEstimate(PN_SAVSM_TABLE_SAMPLER table, sampler2D mip, PnLight light,
//                           vec3 receiver, vec2 unitRange, PnSavsmSettings settings)
//   PnSavsmStats pnSavsmRectStats(PN_SAVSM_TABLE_SAMPLER table, PnRect rect, vec2 unitRange)
//         mean and variance in depth units over a rectangle (4 fetches)
//   float pnSavsmBlockerFromMoments(PnSavsmStats s, float t, float minVariance, float near,
//                                   out bool hasBlocker)           step 2's TABLE estimate
//   receiver: (u, v) shadow-map texels (continuous, texel i spans [i, i + 1)), linear light
//   depth. table: summed_area.glsl's moments table of the N×N map (RGBA32UI fixed point, or
//   RG32F float with PN_SAVSM_TABLE = PN_SAVSM_TABLE_FLOAT); mip: minmax_mip.glsl's chain of
//   the same map (read only when the bound is on or the blocker mode is MIN). unitRange:
//   (near, 1 / (far - near)), what the table was built with.
//   PnSavsmSettings { float bias; float filterScale; float minVariance; float bleedingReduction;
//                     int blockerMode; bool bound; }
//   PnSavsmSettings pnSavsmDefaults(float bias)   filter scale 1, vsm.h's minimum variance and
//         bleeding reduction (1e-4, 0.2), the MIN blocker, the bound on (savsm.h)
//   PnSavsm { PnRect searchRect; PnRect filterRect; float blocker; bool hasBlocker;
//             float filterSide; float mean; float variance; float chebyshev; float reduced;
//             float bound; float visibility; }   (F's moments and each step's value)
//
// options (savsm.h): PN_SAVSM_TABLE (fixed or float), PN_SAVSM_FILTER_SCALE;
//   vsm.h's PN_VSM_MIN_VARIANCE and PN_VSM_BLEEDING_REDUCTION are the defaults
//   the runner passes; summed_area.h's PN_SUMMED_AREA_MOMENT_BITS.
//
// cost: at most 26 fetches a receiver (two rectangles from the table, 4 each;
//   two squares from the mip chain, at most 9 each), whatever S and F
//   measure; a few dozen ALU operations and three divisions. The table's
//   build is summed_area.glsl's (two passes over the map).
//
// isa budget: vgprs 40, instructions 700, code 4096, scratch 0
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_SAVSM_GLSL
#define PENUMBRA_SAVSM_GLSL

#include "savsm.h"
#include "light_model.glsl"
#include "minmax_mip.glsl"
#include "region.glsl"
#include "summed_area.glsl"
#include "variance_bound.glsl"  // and vsm.h

#if PN_SAVSM_TABLE == PN_SAVSM_TABLE_FLOAT
#define PN_SAVSM_TABLE_SAMPLER sampler2D
#else
#define PN_SAVSM_TABLE_SAMPLER usampler2D
#endif

struct PnSavsmSettings {
  float bias;               // a texel occludes when d < dP - bias
  float filterScale;        // c
  float minVariance;        // relative to mu^2 (vsm.glsl)
  float bleedingReduction;  // linstep's a, in [0, PN_VSM_MAX_BLEEDING_REDUCTION]
  int blockerMode;          // PN_SAVSM_BLOCKER_TABLE or _MIN
  bool bound;               // the mip chain's lit test over S and depth-range bound over F
};

// The runner's settings for a bias: the filter scale, minimum variance and bleeding reduction of
// savsm.h and vsm.h, the default blocker mode and the bound.
PnSavsmSettings pnSavsmDefaults(float bias) {
  return PnSavsmSettings(bias, PN_SAVSM_FILTER_SCALE, PN_VSM_MIN_VARIANCE, PN_VSM_BLEEDING_REDUCTION,
                         PN_SAVSM_DEFAULT_BLOCKER, PN_SAVSM_DEFAULT_BOUND != 0);
}

struct PnSavsmStats {
  float mean;      // depth units
  float variance;  // depth units squared
  float texels;    // texels covered
};

struct PnSavsm {
  PnRect searchRect;  // S (empty for a lit pixel without a surface)
  PnRect filterRect;  // F (empty when no blocker was found)
  float blocker;     // z, 0 without a blocker
  bool hasBlocker;
  float filterSide;  // c · penumbra, texels (before rounding)
  float mean;        // F's mean and variance, depth units
  float variance;
  float chebyshev;   // p
  float reduced;     // linstep(a, 1, p)
  float bound;       // PN_VSM_BOUND_* over F (PN_VSM_BOUND_NONE when off or undecided)
  float visibility;
};

PnSavsmStats pnSavsmRectStats(PN_SAVSM_TABLE_SAMPLER table, PnRect rect, vec2 unitRange) {
#if PN_SAVSM_TABLE == PN_SAVSM_TABLE_FLOAT
  PnSummedAreaMoments m = pnSummedAreaRectFloatMoments(table, rect.origin, rect.size);
#else
  PnSummedAreaMoments m = pnSummedAreaRectMoments(table, rect.origin, rect.size);
#endif
  float range = 1.0 / unitRange.y;  // far - near
  return PnSavsmStats(unitRange.x + m.mean * range, m.variance * (range * range), m.texels);
}

// (mu - p t) / (1 - p) with p = v / (v + (t - mu)^2) is mu - v / (t - mu): the same value
// without the cancellation of 1 - p.
float pnSavsmBlockerFromMoments(PnSavsmStats s, float t, float minVariance, float near, out bool hasBlocker) {
  float p = pnVsmChebyshevMeanVariance(s.mean, s.variance, t, minVariance);
  hasBlocker = p < 1.0 - PN_SAVSM_MIN_OCCLUDED;  // t > mu too
  if (!hasBlocker) return 0.0;
  return clamp(s.mean - pnVsmFlooredVariance(s.mean, s.variance, minVariance) / (t - s.mean), near, t);
}

// Min and max over the aligned nodes of the mip chain that cover the rectangle's square (side
// max(size), clipped to the map): a superset of the rectangle, so t <= min and t > max decide
// conservatively; at most 9 fetches.
vec2 pn_savsmSquareMinMax(sampler2D mip, int n, PnRect rect) {
  return pnMipSquareMinMax(mip, n, rect.origin, max(rect.size.x, rect.size.y));
}

PnSavsm pn_savsmLit(PnRect search) {
  PnRect none = PnRect(ivec2(0), ivec2(0));
  return PnSavsm(search, none, 0.0, false, 0.0, 0.0, 0.0, 1.0, 1.0, PN_VSM_BOUND_NONE, 1.0);
}

PnSavsm pnSavsmEstimate(PN_SAVSM_TABLE_SAMPLER table, sampler2D mip, PnLight light, vec3 receiver,
                        vec2 unitRange, PnSavsmSettings settings) {
  PnRect none = PnRect(ivec2(0), ivec2(0));
  float dP = receiver.z;
  if (!pn_summedAreaFinite(dP) || !pn_summedAreaFinite(receiver.x) || !pn_summedAreaFinite(receiver.y))
    return pn_savsmLit(none);
  int n = textureSize(table, 0).x - 1;
  float t = dP - settings.bias;
  PnSavsm r = pn_savsmLit(pnRegionSquare(receiver.xy, pnLightSearchWidthTexels(light, dP), n));
  if (r.searchRect.size.x == 0 || r.searchRect.size.y == 0) return r;

  // 1-2: the blocker search.
  bool readMip = settings.bound || settings.blockerMode == PN_SAVSM_BLOCKER_MIN;
  vec2 searchMinMax = readMip ? pn_savsmSquareMinMax(mip, n, r.searchRect) : vec2(0.0);
  if (settings.bound && t <= searchMinMax.x) return r;
  if (settings.blockerMode == PN_SAVSM_BLOCKER_MIN) {
    r.hasBlocker = searchMinMax.x < t;
    r.blocker = r.hasBlocker ? searchMinMax.x : 0.0;
  } else {
    PnSavsmStats s = pnSavsmRectStats(table, r.searchRect, unitRange);
    r.blocker = pnSavsmBlockerFromMoments(s, t, settings.minVariance, light.near, r.hasBlocker);
  }
  if (!r.hasBlocker) return r;

  // 3: the penumbra and the filter square.
  float side = settings.filterScale * pnLightPenumbraTexels(light, dP, r.blocker);
  r.filterSide = (side >= 0.0 && !isinf(side)) ? side : 0.0;
  r.filterRect = pnRegionSquare(receiver.xy, r.filterSide, n);
  if (r.filterRect.size.x == 0 || r.filterRect.size.y == 0) return r;  // the receiver's texel is off the map: lit

  // 4: the filter's moments, Chebyshev, bleeding reduction, depth-range bound.
  PnSavsmStats f = pnSavsmRectStats(table, r.filterRect, unitRange);
  r.mean = f.mean;
  r.variance = f.variance;
  r.chebyshev = pnVsmChebyshevMeanVariance(f.mean, f.variance, t, settings.minVariance);
  r.reduced = pnVsmReduceBleeding(r.chebyshev, settings.bleedingReduction);
  r.bound = settings.bound ? pnVsmDepthRangeBound(pn_savsmSquareMinMax(mip, n, r.filterRect), t) : PN_VSM_BOUND_NONE;
  r.visibility = pn_vsmApplyBound(r.bound, r.reduced);
  return r;
}

float pnSavsm(PN_SAVSM_TABLE_SAMPLER table, sampler2D mip, PnLight light, vec3 receiver, vec2 unitRange,
              PnSavsmSettings settings) {
  return pnSavsmEstimate(table, mip, light, receiver, unitRange, settings).visibility;
}

#endif  // PENUMBRA_SAVSM_GLSL
