// region.glsl — power-of-two region approximation (seed 000 §2.2, Steps 1–7).
//
// description:
//   Replaces the square search/filter region of side s centred at (x, y)
//   (texels, float) by one 2^j×2^j window, i.e. one texel of depth_pyramid
//   level j. The paper's steps, literally (SPEC §4.2 fixes the open readings):
//   1  l = floor(x - s/2), r = ceil(x + s/2), t = floor(y - s/2), b = ceil(y + s/2)
//      (evaluated in float32)
//   2  clamp the bounds to the map [0, e-1], e = N
//   3  w = r - l + 1, h = b - t + 1; if w is a power of two, w' = w (likewise h)
//   4  otherwise, if the second-highest set bit of w is 1, w' = 2^(floor(lb w) + 1),
//      else w' = 2^floor(lb w)
//   5  s' = w' if w' == h', else min(2 min(w', h'), E), E = the largest power of two <= N
//   6  x' = l + s'/2, y' = t + s'/2
//   7  if x' + s'/2 - 1 >= e then x' = e - 1 - s'/2 + 1 (likewise y')
//   Window: origin (x' - s'/2, y' - s'/2), side s', level j = lb s'.
//   Readings beyond the paper, each needed for a window inside the map:
//   - Step 2 clamps every bound into [0, e-1] (the paper clamps l, t from
//     below and r, b from above only); a region wholly outside the map thus
//     becomes the nearest edge texels instead of a negative width.
//   - The cap E applies in both branches of Step 5: w' = h' can exceed N
//     (w = h = N = 100 rounds to 128).
//   - s NaN or negative reads as 0, a NaN centre coordinate as 0; ±Inf clamps.
//
// use:
//   PnWindow pnRegionApproximate(vec2 centre, float side, int mapSize)          the literal steps
//   PnWindow pnRegionApproximateCentred(vec2 centre, float side, int mapSize)   option: same side s',
//            origin round(centre - s'/2) clamped into the map, so the window stays
//            centred on the original region instead of its clamped top-left corner
//   PnRect pnRegionSquare(vec2 centre, float side, int mapSize)   the exact region (no
//            approximation, for exact PCSS and the "exact region" mode): n = max(1, round(s))
//            texels a side, the n×n block whose texel centres are nearest (x, y) —
//            origin floor(centre - n/2 + 0.5) — clipped to the map; empty when it
//            lies wholly outside (a receiver outside the light's frustum).
//   PnArea pnRegionArea(vec2 centre, float side, int mapSize)   the exact region with
//            area-weighted edges (issue 51): the continuous square of side s = clamp(side, 1, 4N)
//            centred on (x, y) — texel i spans [i, i + 1) — clipped to the map [0, N]²: its bounds
//            lo, hi (texels, float; hi == lo on an axis where it misses the map) and `cover`, the
//            texels it touches, [floor(lo), ceil(hi)). A texel weighs the area of its overlap with
//            it: 1 inside, a fraction on the edges and corners, 0 outside.
//            It moves with its centre by any fraction of a texel, where pnRegionSquare's texels
//            jump a whole texel at a time (the staircase of small maps).
//   float pnRegionAreaSpan(PnArea a, int texel, int axis)   texel [i, i + 1)'s overlap with a
//            along one axis (0: x, 1: y); a texel's weight is the product of its two spans
//   PnArea pnRegionAreaOfRect(PnRect r)   a rectangle as an area: its integer bounds, every texel
//            of it weight 1 (the traversal's one form for both kinds of region)
//   float pnRegionAreaOver(PnArea a, ivec2 lo, ivec2 hi)   the area of a's overlap with the texels
//            [lo, hi): the product of its two spans — for an integer area the texel count exactly
//            (x · y < 2^24), for a continuous one the texels' overlap weights summed
//   int pnRegionRoundPow2(int w)       Steps 3–4 for one extent (w >= 1)
//   int pnRegionLargestPow2(int n)     E
//   PnWindow { ivec2 origin; int side; int level; }: origin + side <= N on both axes.
//   PnArea { vec2 lo; vec2 hi; PnRect cover; }: 0 <= lo <= hi <= N; cover's size 0 where hi == lo.
//
// cost: a few dozen ALU operations, no memory access.

#ifndef PENUMBRA_REGION_GLSL
#define PENUMBRA_REGION_GLSL

struct PnWindow {
  ivec2 origin;
  int side;
  int level;
};

struct PnRect {
  ivec2 origin;
  ivec2 size;  // 0 on an axis where the region misses the map
};

int pnRegionLargestPow2(int n) {
  return 1 << findMSB(max(n, 1));
}

int pnRegionRoundPow2(int w) {
  int top = findMSB(max(w, 1));
  if (w <= (1 << top)) return 1 << top;  // lb w is an integer (or w < 1: treated as 1)
  bool secondBit = ((w >> (top - 1)) & 1) != 0;
  return secondBit ? (1 << (top + 1)) : (1 << top);
}

float pn_regionFiniteOrZero(float v) {
  return isnan(v) ? 0.0 : v;
}

// Steps 1–5: the clamped bounds (l, t) and the side s'.
ivec3 pn_regionCornerAndSide(vec2 centre, float side, int mapSize) {
  int e = max(mapSize, 1);
  float s = max(pn_regionFiniteOrZero(side), 0.0);
  vec2 c = vec2(pn_regionFiniteOrZero(centre.x), pn_regionFiniteOrZero(centre.y));
  float last = float(e - 1);
  // Bounds are clamped while still float, so huge or infinite inputs never
  // reach an int conversion.
  int l = int(clamp(floor(c.x - s * 0.5), 0.0, last));
  int r = int(clamp(ceil(c.x + s * 0.5), 0.0, last));
  int t = int(clamp(floor(c.y - s * 0.5), 0.0, last));
  int b = int(clamp(ceil(c.y + s * 0.5), 0.0, last));
  int w = pnRegionRoundPow2(r - l + 1);
  int h = pnRegionRoundPow2(b - t + 1);
  int cap = pnRegionLargestPow2(e);
  int sp = (w == h) ? w : 2 * min(w, h);
  return ivec3(l, t, min(sp, cap));
}

PnWindow pnRegionApproximate(vec2 centre, float side, int mapSize) {
  int e = max(mapSize, 1);
  ivec3 lts = pn_regionCornerAndSide(centre, side, e);
  float halfSide = float(lts.z) * 0.5;
  vec2 c = vec2(lts.xy) + halfSide;  // Step 6
  // Step 7: push back inside on the right and bottom.
  if (c.x + halfSide - 1.0 >= float(e)) c.x = float(e) - 1.0 - halfSide + 1.0;
  if (c.y + halfSide - 1.0 >= float(e)) c.y = float(e) - 1.0 - halfSide + 1.0;
  return PnWindow(ivec2(c - halfSide), lts.z, findMSB(lts.z));
}

PnWindow pnRegionApproximateCentred(vec2 centre, float side, int mapSize) {
  int e = max(mapSize, 1);
  int sp = pn_regionCornerAndSide(centre, side, e).z;
  vec2 c = vec2(pn_regionFiniteOrZero(centre.x), pn_regionFiniteOrZero(centre.y));
  vec2 origin = clamp(floor(c - float(sp) * 0.5 + 0.5), vec2(0.0), vec2(float(e - sp)));
  return PnWindow(ivec2(origin), sp, findMSB(sp));
}

// The centre pnRegionSquare reads: NaN as 0, clamped while float to [-4, 5] map sides.
vec2 pn_regionSquareCentre(vec2 centre, int mapSize) {
  int e = max(mapSize, 1);
  return clamp(vec2(pn_regionFiniteOrZero(centre.x), pn_regionFiniteOrZero(centre.y)), vec2(float(-4 * e)),
               vec2(float(5 * e)));
}

// pnRegionSquare about a centre pn_regionSquareCentre made for the same map: a caller whose
// squares share one centre (Fast PCSS's refinements and regions) reads it once. The corners are
// clamped as integers (the values clamping them as floats gives: whole numbers far below 2^24),
// so a caller's loop holds the map's side as the integer it has, not as a float too.
PnRect pn_regionSquareAbout(vec2 c, float side, int mapSize) {
  int e = max(mapSize, 1);
  // Clamped while float: an infinite side covers the map, never overflows an int.
  float n = clamp(round(max(pn_regionFiniteOrZero(side), 0.0)), 1.0, float(4 * e));
  ivec2 lo = ivec2(floor(c - 0.5 * n + 0.5));
  ivec2 start = clamp(lo, ivec2(0), ivec2(e));
  ivec2 end = clamp(lo + int(n), start, ivec2(e));
  return PnRect(start, end - start);
}

PnRect pnRegionSquare(vec2 centre, float side, int mapSize) {
  return pn_regionSquareAbout(pn_regionSquareCentre(centre, mapSize), side, mapSize);
}

struct PnArea {
  vec2 lo;       // the clipped square's corners, texels: 0 <= lo <= hi <= N
  vec2 hi;
  PnRect cover;  // the texels it touches: [floor(lo), ceil(hi)), empty where hi == lo
};

// pnRegionArea about a centre pn_regionSquareCentre made for the same map (as pn_regionSquareAbout).
PnArea pn_regionAreaAbout(vec2 c, float side, int mapSize) {
  int e = max(mapSize, 1);
  // Clamped while float, as pnRegionSquare's side: an infinite side covers the map.
  float half_ = 0.5 * clamp(max(pn_regionFiniteOrZero(side), 0.0), 1.0, float(4 * e));
  vec2 lo = clamp(c - half_, vec2(0.0), vec2(float(e)));
  vec2 hi = clamp(c + half_, lo, vec2(float(e)));
  // A square that misses the map on an axis has lo == hi == 0 or N there: no texel.
  ivec2 start = ivec2(floor(lo));
  return PnArea(lo, hi, PnRect(start, ivec2(ceil(hi)) - start));
}

PnArea pnRegionArea(vec2 centre, float side, int mapSize) {
  return pn_regionAreaAbout(pn_regionSquareCentre(centre, mapSize), side, mapSize);
}

PnArea pnRegionAreaOfRect(PnRect r) {
  return PnArea(vec2(r.origin), vec2(r.origin + r.size), r);  // an empty rectangle: hi <= lo, no texel
}

float pnRegionAreaOver(PnArea a, ivec2 lo, ivec2 hi) {
  vec2 span = max(min(vec2(hi), a.hi) - max(vec2(lo), a.lo), vec2(0.0));
  return span.x * span.y;
}

float pnRegionAreaSpan(PnArea a, int texel, int axis) {
  float t = float(texel);
  return max(min(t + 1.0, a.hi[axis]) - max(t, a.lo[axis]), 0.0);
}

#endif  // PENUMBRA_REGION_GLSL
