// pcf.glsl — brute-force blocker search and percentage-closer filtering over a
// rectangular window of the shadow map (what exact PCSS does).
//
// description:
//   SPEC §3, §4.8 ("exact PCSS"). For receiver depth dP, a bias and the
//   window W = [origin, origin + size) of texels, every texel of W that lies
//   in the map is fetched once:
//     occluders = #{ q in W : d(q) < dP - bias }
//     depthSum  = sum of d(q) over those texels
//     texels    = #{ q in W }                     (the texels covered)
//   so blocker mean = depthSum / occluders (PCSS's blocker search) and
//   occluded fraction = occluders / texels (PCF; visibility = 1 - fraction).
//   Non-finite texels (NaN, ±Inf) never occlude (SPEC §3): they count as
//   covered, never as occluders, and never enter depthSum, so no NaN comes
//   out of a map that holds them. A NaN receiver depth occludes nothing.
//   The window is clipped to the map; of what remains, at most
//   PN_PCF_MAX_SIDE columns and rows (from its top-left texel) are read —
//   the loop bound. Origins and sizes in texels; origin + size and
//   firstRow + rowCount must not overflow an int (if they do, which texels
//   are read is unspecified, but no read ever leaves the map). Sizes <= 0
//   give an empty window.
//   Banded scans: pnPcfAddRows adds only the window's rows that fall in
//   [firstRow, firstRow + rowCount) to running sums, in row order, so that a
//   caller can split a large window over several dispatches (llvmpipe ends
//   an invocation's loops after 65535 iterations in total) and get exactly
//   the sums of one whole-window scan, bit for bit: the additions happen in
//   the same order. Within a row, PN_PCF_ROW_STEP texels are handled per
//   loop iteration (a constant-trip inner loop that compilers unroll), so a
//   band of r rows of a w-wide window costs r * (ceil(w / PN_PCF_ROW_STEP) + 1)
//   loop iterations.
//
// The call (the hard shadow a lighting shader takes, what a hardware shadow sampler with linear
// filtering gives):
//   float pnPcf(sampler2D depthMap, vec3 receiver, float bias)   receiver = (u, v, d) as
//         pnLightProject gives (light_model.glsl): pnPcfBilinearVisibility at (u, v) for depth d
//   float pnPcf(sampler2D depthMap, vec3 receiver, vec2 receiverPlane, float bias)
//         with a receiver-plane depth bias (receiver_plane.glsl): each of the four texels tested
//         against the receiver's plane at its own centre (pnPcfBilinearVisibilityPlane); vec2(0)
//         is the call above exactly
//
// use:
//   PnPcf pnPcfWindow(sampler2D depthMap, ivec2 origin, ivec2 size, float receiverDepth, float bias)
//   PnPcf pnPcfAddRows(sampler2D depthMap, ivec2 origin, ivec2 size, float receiverDepth, float bias,
//                      int firstRow, int rowCount, PnPcf sums)      sums + the band's rows (map rows)
//   PnPcf pnPcfWindowPlane(sampler2D depthMap, ivec2 origin, ivec2 size, vec3 receiver, vec2 gradient,
//                          float bias)          with a receiver plane (receiver_plane.glsl): texel q
//         occludes when d(q) < d - bias + gradient · (q + 1/2 - (u, v)), receiver = (u, v, d);
//         gradient 0 is pnPcfWindow exactly (pnPcfAddRowsPlane: the same for a band of rows)
//   PnPcf pnPcfAreaPlane(sampler2D depthMap, PnArea area, vec3 receiver, vec2 gradient, float bias)
//         the area-weighted window (region.glsl's pnRegionArea, issue 51): every texel of
//         area.cover in the map counts with its overlap w with the square (pnRegionAreaSpan's
//         product): occluders = sum of w over the occluding texels, depthSum = sum of w d over them,
//         texels = sum of w (the square's area inside the map, read); gradient 0: no receiver plane.
//         The same PN_PCF_MAX_SIDE bound from the cover's clipped top-left texel.
//   PnPcf pnPcfAddAreaRowsPlane(sampler2D depthMap, PnArea area, vec3 receiver, vec2 gradient,
//                               float bias, int firstRow, int rowCount, PnPcf sums)
//         sums + the band's rows, as pnPcfAddRows: bands in row order add up to the whole call
//   PnPcf pnPcfZero()
//   float pnPcfBilinearVisibility(sampler2D depthMap, vec2 position, float receiverDepth, float bias)
//         hard shadow with 2×2 bilinear PCF (what a hardware shadow sampler does; seed 003's
//         "PCF 2×2" baseline): the shadow test at the four texels whose centres surround
//         `position` (continuous texels, texel i's centre at i + 0.5; clamped to the map),
//         weighted bilinearly; 1 lit, 0 in shadow. A NaN or infinite position is lit.
//   float pnPcfBilinearVisibilityPlane(sampler2D depthMap, vec3 receiver, vec2 gradient, float bias)
//         the same at receiver.xy, each texel read (after the clamp) against its own threshold
//         receiver.z - bias + gradient · (q + 1/2 - receiver.xy)
//   float pnPcfBlockerMean(PnPcf s)         depthSum / occluders, 0 without occluders
//   float pnPcfOccludedFraction(PnPcf s)    occluders / texels, at most 1; 0 without texels
//   bool  pnPcfOccludes(float depth, float threshold)   depth < threshold and finite
//   struct PnPcf { float occluders; float depthSum; float texels; }
//   depthMap: linear light depth in .r (R32F, or any float format; one level,
//   texelFetch only, no filtering), textureSize(depthMap, 0) texels.
//   Counts travel as floats: exact up to 2^24 texels (a 4096² window).
//
// options:
//   PN_PCF_MAX_SIDE   loop bound: most columns and rows read per window (8192)
//   PN_PCF_ROW_STEP   texels per inner loop iteration (16)
//
// cost: one texelFetch and one compare per covered texel; w·h fetches for a
//   w×h window (exact PCSS: O(s²) per pixel for a side-s region).
//
// isa budget: vgprs 16, instructions 200, code 1024, scratch 0
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_PCF_GLSL
#define PENUMBRA_PCF_GLSL

#include "receiver_plane.glsl"
#include "region.glsl"

#ifndef PN_PCF_MAX_SIDE
#define PN_PCF_MAX_SIDE 8192
#endif
#ifndef PN_PCF_ROW_STEP
#define PN_PCF_ROW_STEP 16
#endif

struct PnPcf {
  float occluders;  // texels with depth < dP - bias
  float depthSum;   // their depth sum
  float texels;     // texels covered (read)
};

PnPcf pnPcfZero() {
  return PnPcf(0.0, 0.0, 0.0);
}

bool pnPcfOccludes(float depth, float threshold) {
  // NaN compares false; +Inf is never below a threshold; -Inf is excluded here (one compare:
  // isinf's |depth| == Inf costs two a texel).
  return depth < threshold && depth > uintBitsToFloat(0xff800000u);
}

float pnPcfBlockerMean(PnPcf s) {
  return s.occluders > 0.0 ? s.depthSum / s.occluders : 0.0;
}

float pnPcfOccludedFraction(PnPcf s) {
  // At most 1: area-weighted rows (pnPcfAreaPlane) sum in another order than the window's area.
  return s.texels > 0.0 ? min(s.occluders / s.texels, 1.0) : 0.0;
}

PnPcf pnPcfAddRowsPlane(sampler2D depthMap, ivec2 origin, ivec2 size, vec3 receiver, vec2 gradient, float bias,
                        int firstRow, int rowCount, PnPcf sums) {
  ivec2 n = textureSize(depthMap, 0);
  // Clip to the map, then bound each side by PN_PCF_MAX_SIDE from the clipped origin.
  ivec2 lo = clamp(origin, ivec2(0), n);
  ivec2 hi = clamp(origin + max(size, ivec2(0)), lo, n);
  hi = min(hi, lo + ivec2(PN_PCF_MAX_SIDE));
  int rowStart = max(lo.y, firstRow);
  int rowEnd = min(hi.y, firstRow + max(rowCount, 0));
  float t = receiver.z - bias;
  for (int y = rowStart; y < rowEnd; ++y) {
    for (int x = lo.x; x < hi.x; x += PN_PCF_ROW_STEP) {
      for (int i = 0; i < PN_PCF_ROW_STEP; ++i) {  // constant trip count: unrolled
        if (x + i < hi.x) {
          float d = texelFetch(depthMap, ivec2(x + i, y), 0).r;
          if (pnPcfOccludes(d, pnReceiverPlaneThreshold(t, gradient, receiver.xy, ivec2(x + i, y)))) {
            sums.occluders += 1.0;
            sums.depthSum += d;
          }
        }
      }
    }
    sums.texels += float(hi.x - lo.x);
  }
  return sums;
}

PnPcf pnPcfAddRows(sampler2D depthMap, ivec2 origin, ivec2 size, float receiverDepth, float bias, int firstRow,
                   int rowCount, PnPcf sums) {
  return pnPcfAddRowsPlane(depthMap, origin, size, vec3(0.0, 0.0, receiverDepth), vec2(0.0), bias, firstRow, rowCount,
                           sums);
}

PnPcf pnPcfWindowPlane(sampler2D depthMap, ivec2 origin, ivec2 size, vec3 receiver, vec2 gradient, float bias) {
  return pnPcfAddRowsPlane(depthMap, origin, size, receiver, gradient, bias, 0, textureSize(depthMap, 0).y,
                           pnPcfZero());
}

PnPcf pnPcfWindow(sampler2D depthMap, ivec2 origin, ivec2 size, float receiverDepth, float bias) {
  // Every row of the map: the clipped window's rows lie in [0, map height).
  return pnPcfAddRows(depthMap, origin, size, receiverDepth, bias, 0, textureSize(depthMap, 0).y, pnPcfZero());
}

PnPcf pnPcfAddAreaRowsPlane(sampler2D depthMap, PnArea area, vec3 receiver, vec2 gradient, float bias, int firstRow,
                            int rowCount, PnPcf sums) {
  ivec2 n = textureSize(depthMap, 0);
  ivec2 lo = clamp(area.cover.origin, ivec2(0), n);
  ivec2 hi = clamp(area.cover.origin + max(area.cover.size, ivec2(0)), lo, n);
  hi = min(hi, lo + ivec2(PN_PCF_MAX_SIDE));
  int rowStart = max(lo.y, firstRow);
  int rowEnd = min(hi.y, firstRow + max(rowCount, 0));
  float t = receiver.z - bias;
  for (int y = rowStart; y < rowEnd; ++y) {
    // The columns between the first and the last weigh exactly 1: they are read as the integer
    // window's are, and only the two edge columns weigh their overlap (the ring's arithmetic).
    PnPcf row = pnPcfZero();
    for (int x = lo.x + 1; x < hi.x - 1; x += PN_PCF_ROW_STEP) {
      for (int i = 0; i < PN_PCF_ROW_STEP; ++i) {  // constant trip count: unrolled
        if (x + i < hi.x - 1) {
          float d = texelFetch(depthMap, ivec2(x + i, y), 0).r;
          if (pnPcfOccludes(d, pnReceiverPlaneThreshold(t, gradient, receiver.xy, ivec2(x + i, y)))) {
            row.occluders += 1.0;
            row.depthSum += d;
          }
        }
      }
    }
    row.texels = float(max(hi.x - lo.x - 2, 0));
    for (int e = 0; e < 2; ++e) {
      int x = e == 0 ? lo.x : hi.x - 1;
      if (x < hi.x && (e == 0 || x > lo.x)) {  // the cover's first column, then its last (when another)
        float w = pnRegionAreaSpan(area, x, 0);
        float d = texelFetch(depthMap, ivec2(x, y), 0).r;
        if (pnPcfOccludes(d, pnReceiverPlaneThreshold(t, gradient, receiver.xy, ivec2(x, y)))) {
          row.occluders += w;
          row.depthSum += w * d;
        }
        row.texels += w;
      }
    }
    float wy = pnRegionAreaSpan(area, y, 1);
    sums.occluders += wy * row.occluders;
    sums.depthSum += wy * row.depthSum;
    sums.texels += wy * row.texels;
  }
  return sums;
}

PnPcf pnPcfAreaPlane(sampler2D depthMap, PnArea area, vec3 receiver, vec2 gradient, float bias) {
  return pnPcfAddAreaRowsPlane(depthMap, area, receiver, gradient, bias, 0, textureSize(depthMap, 0).y, pnPcfZero());
}

// The texel at p, clamped to the map: lit (1) unless it occludes its own
// threshold (the test's at the texel read).
float pn_pcfLitAt(sampler2D depthMap, ivec2 p, vec3 receiver, vec2 gradient, float threshold) {
  ivec2 q = clamp(p, ivec2(0), textureSize(depthMap, 0) - ivec2(1));
  float t = pnReceiverPlaneThreshold(threshold, gradient, receiver.xy, q);
  return pnPcfOccludes(texelFetch(depthMap, q, 0).r, t) ? 0.0 : 1.0;
}

float pnPcfBilinearVisibilityPlane(sampler2D depthMap, vec3 receiver, vec2 gradient, float bias) {
  vec2 p = receiver.xy - vec2(0.5);  // texel i's centre is i + 0.5
  vec2 cell = floor(p);
  vec2 f = p - cell;
  if (any(isnan(f)) || any(isinf(receiver.xy))) return 1.0;  // no position: nothing can be tested
  ivec2 i = ivec2(clamp(cell, vec2(-2.0), vec2(textureSize(depthMap, 0))));
  float t = receiver.z - bias;
  float top = mix(pn_pcfLitAt(depthMap, i, receiver, gradient, t),
                  pn_pcfLitAt(depthMap, i + ivec2(1, 0), receiver, gradient, t), f.x);
  float bottom = mix(pn_pcfLitAt(depthMap, i + ivec2(0, 1), receiver, gradient, t),
                     pn_pcfLitAt(depthMap, i + ivec2(1, 1), receiver, gradient, t), f.x);
  return mix(top, bottom, f.y);
}

float pnPcfBilinearVisibility(sampler2D depthMap, vec2 position, float receiverDepth, float bias) {
  return pnPcfBilinearVisibilityPlane(depthMap, vec3(position, receiverDepth), vec2(0.0), bias);
}

float pnPcf(sampler2D depthMap, vec3 receiver, vec2 receiverPlane, float bias) {
  return pnPcfBilinearVisibilityPlane(depthMap, receiver, receiverPlane, bias);
}

float pnPcf(sampler2D depthMap, vec3 receiver, float bias) {
  return pnPcf(depthMap, receiver, vec2(0.0), bias);
}

#endif  // PENUMBRA_PCF_GLSL
