// summed_area.glsl — summed-area table of a depth map in 64-bit fixed point
// with wrap-around arithmetic, and the sum over any texel rectangle from
// four fetches; moments tables (sums of x and x² of the unit depth, fixed
// point or float) and a rectangle's mean and variance from them.
//
// description:
//   SPEC §5 (summed-area tables for seed 004's variance soft shadows; the
//   clipped depth sums of seed 000's exact-region traversal). Each finite
//   depth d becomes the integer q(d) = roundEven(clamp(d, ±2^(52-F)) * 2^F)
//   (F = PN_SUMMED_AREA_FRACTION_BITS, step 2^-F in depth units), held as a
//   64-bit two's complement number in two uints. For an N×M map the table T
//   is (N+1)×(M+1) texels of uvec4 (sum low word, sum high word, finite
//   count, 0):
//     T(x, y) = sum over the texels [0, x) × [0, y) of (q(d), finite(d))
//   with every addition taken modulo 2^64 (sum) and 2^32 (count). Row 0 and
//   column 0 are zero, so a rectangle [x0, x1) × [y0, y1) is
//     T(x1, y1) - T(x0, y1) - T(x1, y0) + T(x0, y0)          (4 fetches)
//   Modular arithmetic is a ring homomorphism: that difference equals the
//   exact integer sum of q over the rectangle modulo 2^64, however often the
//   prefix sums wrapped, so it IS the exact sum (read as signed) whenever
//   |sum of q| < 2^63 — e.g. any rectangle of up to 2^24 texels (a 4096²
//   map) of depths below 2^19 in magnitude at F = 20. No rounding anywhere
//   until the one conversion of the result to float (relative error
//   <= 2^-23 (1 + 2^-25)). Against the raw depths, the only other error is
//   the quantisation: none for |d| >= 2^(23-F) (such floats are multiples of
//   2^-F), at most 2^-(F+1) per texel below that.
//   Non-finite depths (NaN, ±Inf: "no occluder", SPEC §3) are excluded: they
//   add 0 to the sum and 0 to the finite count, so nothing is poisoned; the
//   rectangle's texels covered minus its finite count is how many it holds.
//   A blocker mean needs the sum over occluding texels only; a traversal node
//   that occludes wholly (dP - bias above its max: every texel finite and
//   occluding) has exactly that in its clipped rectangle's plain sum and
//   count, and a node that does not is descended, never summed here.
//   Rectangles are clipped to the map (origin may lie outside; sizes <= 0
//   give an empty rectangle); every fetch is inside the table.
//   Moments tables (seed 004's summed-area VSM): the first two moments of
//   the unit depth x = clamp((d - near) / (far - near), 0, 1), every texel
//   counted (a non-finite one is x = 1, the far plane). Fixed point: q =
//   roundEven(x * 2^B), the table holds sum q and sum q^2 modulo 2^64, so a
//   rectangle's sums are exact; its variance is taken centred on the
//   rounded mean c, sum (q - c)^2 exactly in 64 bits, then one division in
//   float — no cancellation. Error against the true x: the quantisation,
//   2^-(B+1) a texel (1.9e-6 at B = 18: (far - near) * 1.9e-6 in depth), a
//   few u of float rounding, and 2 sigma e + e^2 on the variance. Float
//   (for comparison; Lauritzen's centred fp32 table): sums of x - 1/2 and
//   (x - 1/2)^2, whose prefixes grow with the map: at 2048^2 a texel's mean
//   comes back in steps of 1/16.
//   Build, in two passes of one invocation per line: a row-prefix table R
//   (R(x+1, y+1) = R(x, y+1) + texel (x, y) of the map; row 0 and column 0
//   zero), each row r a loop over x of left = pnSummedAreaRowStep(map, r, x,
//   left), stored at (x, r); then T, each column c a loop over y of above =
//   pnSummedAreaColumnStep(R, c, y, above), stored at (c, y). The loops and
//   stores are the caller's (passes/summed_area_build.comp): an image cannot
//   be a function parameter in Vulkan GLSL (glslang's SPIR-V drops its
//   format), so the module takes none. N+1 or M+1 iterations a line,
//   bounded through pnSummedAreaTableSize (llvmpipe-safe below 65535).
//
// use:
//   ivec2 pnSummedAreaTableSize(ivec2 mapSize)   (N+1, M+1), sides bounded by PN_SUMMED_AREA_MAX_SIDE + 1
//   uvec4 pnSummedAreaRowStep(sampler2D depthMap, int row, int x, uvec4 left)       R(x, row) from R(x-1, row)
//   uvec4 pnSummedAreaColumnStep(usampler2D rowPrefix, int column, int y, uvec4 above)   T(column, y) from T(column, y-1)
//   PnSummedArea pnSummedAreaRectSum(usampler2D table, ivec2 origin, ivec2 size)
//   float pnSummedAreaMean(PnSummedArea s)       sum / count, 0 without finite texels
//   uvec4 pnSummedAreaTexel(float depth)         one texel's (q low, q high, finite, 0)
//   uvec4 pnSummedAreaAdd(uvec4 a, uvec4 b)      modular: 64-bit sum with carry, counts
//   uvec4 pnSummedAreaSub(uvec4 a, uvec4 b)      modular: 64-bit difference with borrow
//   float pnSummedAreaFixedToFloat(uvec2 q)      signed 64-bit q (low, high) times 2^-F
//   struct PnSummedArea { uvec2 fixedSum; float sum; float count; float texels; }
//   Moments tables (x the unit depth; unitRange = (offset, scale) = (near, 1 / (far - near))):
//   float pnSummedAreaUnitDepth(float depth, vec2 unitRange)   x = clamp((d - offset) * scale, 0, 1), 1 if not finite
//   uint pnSummedAreaMomentQ(float depth, vec2 unitRange)      q = roundEven(x * 2^B)
//   uvec4 pnSummedAreaMomentsTexel(float depth, vec2 unitRange)       (q, 0, q^2 low, high)
//   vec4 pnSummedAreaFloatMomentsTexel(float depth, vec2 unitRange)   (x - 1/2, (x - 1/2)^2, 0, 0)
//   uvec4 pnSummedAreaMomentsRowStep(sampler2D depthMap, vec2 unitRange, int row, int x, uvec4 left)
//   uvec4 pnSummedAreaMomentsColumnStep(usampler2D rowPrefix, int column, int y, uvec4 above)
//   vec4 pnSummedAreaFloatMomentsRowStep(sampler2D depthMap, vec2 unitRange, int row, int x, vec4 left)
//   vec4 pnSummedAreaFloatMomentsColumnStep(sampler2D rowPrefix, int column, int y, vec4 above)
//   uvec4 pnSummedAreaMomentsAdd(uvec4 a, uvec4 b), pnSummedAreaMomentsSub   two 64-bit words each, modular
//   uvec4 pnSummedAreaRectMomentSums(usampler2D table, ivec2 origin, ivec2 size, out uint texels)
//                                                 (sum q low, high, sum q^2 low, high), exact mod 2^64
//   PnSummedAreaMoments pnSummedAreaRectMoments(usampler2D table, ivec2 origin, ivec2 size)   fixed point
//   PnSummedAreaMoments pnSummedAreaRectFloatMoments(sampler2D table, ivec2 origin, ivec2 size)   float
//   struct PnSummedAreaMoments { float mean; float variance; float texels; }   of x; 0, 0, 0 when empty
//   Moments tables: RGBA32UI (fixed) or RG32F (float; RGBA32F on ES), (N+1)×(M+1), built like the
//   depth-sum table by passes/summed_area_build.comp (PN_SUMMED_AREA_BUILD_KIND).
//   depthMap: linear light depth in .r (R32F), N×M texels, 1 <= N, M <=
//   PN_SUMMED_AREA_MAX_SIDE. rowPrefix and table: RGBA32UI, (N+1)×(M+1) —
//   written through a writeonly rgba32ui image, read through a usampler2D
//   (no read-write image, so GLSL ES 3.10 runs it: one of its 4 image
//   units per build pass). origin, size in texels of the map; origin + size
//   must not overflow an int. Counts travel as floats: exact up to 2^24.
//
// options:
//   PN_SUMMED_AREA_FRACTION_BITS   F, the fixed-point step 2^-F (20)
//   PN_SUMMED_AREA_MAX_SIDE        loop bound: largest map side (16384)
//   PN_SUMMED_AREA_MOMENT_BITS     B, the moments' step 2^-B of x (18, at most 18)
//   (in summed_area.h, shared with the runner)
//   PN_ON_TEXEL_FETCH()            called at each table fetch of a query (empty; a check counts fetches)
//
// cost: build 2 passes, one fetch, a 64-bit add and a store per table texel
//   (16 bytes a texel: 16 MiB at 1024², plus as much for the row-prefix
//   table while building); query 4 fetches and a few integer operations,
//   whatever the rectangle's size.

#ifndef PENUMBRA_SUMMED_AREA_GLSL
#define PENUMBRA_SUMMED_AREA_GLSL

#include "summed_area.h"  // PN_SUMMED_AREA_FRACTION_BITS, _MAGNITUDE_BITS, _MAX_SIDE, _MOMENT_BITS, _KIND_*

// Called once per table fetch of a rectangle query: empty, unless a caller
// counts fetches (the savsm check's constant-cost case defines it first).
#ifndef PN_ON_TEXEL_FETCH
#define PN_ON_TEXEL_FETCH()
#endif

struct PnSummedArea {
  uvec2 fixedSum;  // sum of q over the finite texels, two's complement mod 2^64: (low word, high word)
  float sum;       // fixedSum as a float times 2^-F: the depth sum
  float count;     // finite texels
  float texels;    // texels covered: the clipped rectangle's area
};

// 2^e, exactly (-126 <= e <= 127).
float pn_summedAreaPow2(int e) {
  return uintBitsToFloat(uint(127 + e) << 23);
}

// NaN and ±Inf have every exponent bit set (a bit test: no reliance on isnan).
bool pn_summedAreaFinite(float v) {
  return (floatBitsToUint(v) & 0x7f800000u) != 0x7f800000u;
}

uvec4 pnSummedAreaTexel(float depth) {
  if (!pn_summedAreaFinite(depth)) return uvec4(0u);
  // Each step exact in float: scaling by powers of two, roundEven, floor, and
  // the split x = hi * 2^32 + lo of an integer x <= 2^52.
  float limit = pn_summedAreaPow2(PN_SUMMED_AREA_MAGNITUDE_BITS - PN_SUMMED_AREA_FRACTION_BITS);
  float x = roundEven(min(abs(depth), limit) * pn_summedAreaPow2(PN_SUMMED_AREA_FRACTION_BITS));
  float high = floor(x * pn_summedAreaPow2(-32));
  uint hi = uint(high);
  uint lo = uint(x - high * pn_summedAreaPow2(32));
  if (depth < 0.0) {  // two's complement negation of (hi, lo)
    lo = ~lo + 1u;
    hi = ~hi + (lo == 0u ? 1u : 0u);
  }
  return uvec4(lo, hi, 1u, 0u);
}

// 64-bit two's complement numbers as (low word, high word), modulo 2^64.
uvec2 pn_summedAreaAdd64(uvec2 a, uvec2 b) {
  uint lo = a.x + b.x;  // uint arithmetic wraps modulo 2^32
  uint carry = lo < a.x ? 1u : 0u;
  return uvec2(lo, a.y + b.y + carry);
}

uvec2 pn_summedAreaSub64(uvec2 a, uvec2 b) {
  uint borrow = a.x < b.x ? 1u : 0u;
  return uvec2(a.x - b.x, a.y - b.y - borrow);
}

uvec4 pnSummedAreaAdd(uvec4 a, uvec4 b) {
  return uvec4(pn_summedAreaAdd64(a.xy, b.xy), a.zw + b.zw);
}

uvec4 pnSummedAreaSub(uvec4 a, uvec4 b) {
  return uvec4(pn_summedAreaSub64(a.xy, b.xy), a.zw - b.zw);
}

// A non-negative 64-bit number (< 2^64, read unsigned) as a float: two conversions and one
// addition of non-negative terms, relative error <= 2u + u^2, u = 2^-24.
float pn_summedAreaUnsignedToFloat(uvec2 q) {
  return float(q.y) * pn_summedAreaPow2(32) + float(q.x);
}

// A two's complement 64-bit number as a float: its magnitude (-2^63 stays 2^63, read unsigned)
// converted, the sign put back; the same relative error.
float pn_summedAreaSignedToFloat(uvec2 q) {
  bool negative = q.y >= 0x80000000u;
  if (negative) q = pn_summedAreaSub64(uvec2(0u), q);
  float magnitude = pn_summedAreaUnsignedToFloat(q);
  return negative ? -magnitude : magnitude;
}

float pnSummedAreaFixedToFloat(uvec2 q) {
  return pn_summedAreaSignedToFloat(q) * pn_summedAreaPow2(-PN_SUMMED_AREA_FRACTION_BITS);  // exact scaling
}

ivec2 pnSummedAreaTableSize(ivec2 mapSize) {
  return clamp(mapSize, ivec2(0), ivec2(PN_SUMMED_AREA_MAX_SIDE)) + ivec2(1);
}

uvec4 pnSummedAreaRowStep(sampler2D depthMap, int row, int x, uvec4 left) {
  if (row <= 0 || x <= 0) return uvec4(0u);  // row 0 and column 0 of the table are zero
  return pnSummedAreaAdd(left, pnSummedAreaTexel(texelFetch(depthMap, ivec2(x - 1, row - 1), 0).r));
}

uvec4 pnSummedAreaColumnStep(usampler2D rowPrefix, int column, int y, uvec4 above) {
  return pnSummedAreaAdd(above, texelFetch(rowPrefix, ivec2(column, y), 0));
}

// The rectangle [origin, origin + size) clipped to an n-texel map: corners (lo, hi) of the table.
ivec4 pn_summedAreaClip(ivec2 n, ivec2 origin, ivec2 size) {
  ivec2 lo = clamp(origin, ivec2(0), n);
  ivec2 hi = clamp(origin + max(size, ivec2(0)), lo, n);
  return ivec4(lo, hi);
}

uvec4 pn_summedAreaFetch(usampler2D table, ivec2 corner) {
  PN_ON_TEXEL_FETCH();
  return texelFetch(table, corner, 0);
}

PnSummedArea pnSummedAreaRectSum(usampler2D table, ivec2 origin, ivec2 size) {
  ivec4 c = pn_summedAreaClip(textureSize(table, 0) - ivec2(1), origin, size);
  ivec2 lo = c.xy, hi = c.zw;
  uvec4 topLeft = pn_summedAreaFetch(table, lo);
  uvec4 topRight = pn_summedAreaFetch(table, ivec2(hi.x, lo.y));
  uvec4 bottomLeft = pn_summedAreaFetch(table, ivec2(lo.x, hi.y));
  uvec4 bottomRight = pn_summedAreaFetch(table, hi);
  uvec4 s = pnSummedAreaSub(pnSummedAreaAdd(bottomRight, topLeft), pnSummedAreaAdd(topRight, bottomLeft));
  PnSummedArea r;
  r.fixedSum = s.xy;
  r.sum = pnSummedAreaFixedToFloat(s.xy);
  r.count = float(s.z);
  r.texels = float((hi.x - lo.x) * (hi.y - lo.y));
  return r;
}

float pnSummedAreaMean(PnSummedArea s) {
  return s.count > 0.0 ? s.sum / s.count : 0.0;
}

// ---- Moments tables (seed 004's summed-area variance shadow maps) ----------

struct PnSummedAreaMoments {
  float mean;      // E[x] over the rectangle, x the unit depth (pnSummedAreaUnitDepth)
  float variance;  // E[x^2] - E[x]^2, >= 0
  float texels;    // texels covered (every texel counts: a non-finite one is x = 1)
};

float pnSummedAreaUnitDepth(float depth, vec2 unitRange) {
  if (!pn_summedAreaFinite(depth)) return 1.0;
  // A subtraction and a multiplication, each correctly rounded (no division, whose GLSL
  // precision is 2.5 ulp): the CPU reference reproduces x bit for bit.
  return clamp((depth - unitRange.x) * unitRange.y, 0.0, 1.0);
}

uint pnSummedAreaMomentQ(float depth, vec2 unitRange) {
  return uint(roundEven(pnSummedAreaUnitDepth(depth, unitRange) * pn_summedAreaPow2(PN_SUMMED_AREA_MOMENT_BITS)));
}

// a · b as 64 bits (low, high word), exact, from 16-bit halves: what GLSL's umulExtended computes,
// written in operations every shading language has (SPIRV-Cross writes umulExtended's SPIR-V
// into HLSL as a call HLSL does not have, so the HLSL export could not compile).
uvec2 pn_summedAreaMulWide(uint a, uint b) {
  uint a0 = a & 0xFFFFu, a1 = a >> 16, b0 = b & 0xFFFFu, b1 = b >> 16;
  uint low = a0 * b0, cross0 = a0 * b1, cross1 = a1 * b0;
  uint middle = (low >> 16) + (cross0 & 0xFFFFu) + (cross1 & 0xFFFFu);  // < 3 · 2^16
  return uvec2((middle << 16) | (low & 0xFFFFu), a1 * b1 + (cross0 >> 16) + (cross1 >> 16) + (middle >> 16));
}

uvec4 pnSummedAreaMomentsTexel(float depth, vec2 unitRange) {
  uint q = pnSummedAreaMomentQ(depth, unitRange);
  uvec2 square = pn_summedAreaMulWide(q, q);  // q^2 < 2^(2B + 1): exact in 64 bits
  return uvec4(q, 0u, square);
}

vec4 pnSummedAreaFloatMomentsTexel(float depth, vec2 unitRange) {
  float v = pnSummedAreaUnitDepth(depth, unitRange) - 0.5;  // centred: Lauritzen's fp32 advice
  return vec4(v, v * v, 0.0, 0.0);
}

uvec4 pnSummedAreaMomentsAdd(uvec4 a, uvec4 b) {
  return uvec4(pn_summedAreaAdd64(a.xy, b.xy), pn_summedAreaAdd64(a.zw, b.zw));
}

uvec4 pnSummedAreaMomentsSub(uvec4 a, uvec4 b) {
  return uvec4(pn_summedAreaSub64(a.xy, b.xy), pn_summedAreaSub64(a.zw, b.zw));
}

uvec4 pnSummedAreaMomentsRowStep(sampler2D depthMap, vec2 unitRange, int row, int x, uvec4 left) {
  if (row <= 0 || x <= 0) return uvec4(0u);
  return pnSummedAreaMomentsAdd(left, pnSummedAreaMomentsTexel(texelFetch(depthMap, ivec2(x - 1, row - 1), 0).r,
                                                               unitRange));
}

uvec4 pnSummedAreaMomentsColumnStep(usampler2D rowPrefix, int column, int y, uvec4 above) {
  return pnSummedAreaMomentsAdd(above, texelFetch(rowPrefix, ivec2(column, y), 0));
}

vec4 pnSummedAreaFloatMomentsRowStep(sampler2D depthMap, vec2 unitRange, int row, int x, vec4 left) {
  if (row <= 0 || x <= 0) return vec4(0.0);
  return left + pnSummedAreaFloatMomentsTexel(texelFetch(depthMap, ivec2(x - 1, row - 1), 0).r, unitRange);
}

vec4 pnSummedAreaFloatMomentsColumnStep(sampler2D rowPrefix, int column, int y, vec4 above) {
  return above + texelFetch(rowPrefix, ivec2(column, y), 0);
}

// (low, high) times a 32-bit m, modulo 2^64.
uvec2 pn_summedAreaMul64(uvec2 a, uint m) {
  uvec2 r = pn_summedAreaMulWide(a.x, m);
  r.y += a.y * m;
  return r;
}

// Mean and variance of x over a rectangle from the fixed-point table: S1 = sum q, S2 = sum q^2
// (exact modulo 2^64), n texels. c = the rounded mean of q (an integer <= 2^B, within
// rho = 1/2 + 7u 2^B of the mean: float(S1) / n is off by 2u + 5u, GLSL's division 2.5 ulp),
// then exactly, modulo 2^64,
//   C = S2 - 2 c S1 + n c^2 = sum (q - c)^2        (in [0, 2^63): summed_area.h)
//   D = S1 - n c            = sum (q - c)          (|D| <= rho n, 0.61 n at B = 18)
// and in float var(q) = C / n - (D / n)^2, with no cancellation beyond (D / n)^2 <= 0.38:
// within 8u var(q) + 20u rho^2 (u = 2^-24), the mean within u mean(q) + 6u rho
// (docs/modules/summed_area.md, "Moments tables").
uvec4 pnSummedAreaRectMomentSums(usampler2D table, ivec2 origin, ivec2 size, out uint texels) {
  ivec4 c = pn_summedAreaClip(textureSize(table, 0) - ivec2(1), origin, size);
  texels = uint((c.z - c.x) * (c.w - c.y));
  return pnSummedAreaMomentsSub(
      pnSummedAreaMomentsAdd(pn_summedAreaFetch(table, c.zw), pn_summedAreaFetch(table, c.xy)),
      pnSummedAreaMomentsAdd(pn_summedAreaFetch(table, c.zy), pn_summedAreaFetch(table, c.xw)));
}

PnSummedAreaMoments pnSummedAreaRectMoments(usampler2D table, ivec2 origin, ivec2 size) {
  uint n;
  uvec4 s = pnSummedAreaRectMomentSums(table, origin, size, n);
  PnSummedAreaMoments m;
  m.texels = float(n);
  if (n == 0u) {
    m.mean = 0.0;
    m.variance = 0.0;
    return m;
  }
  float scale = pn_summedAreaPow2(-PN_SUMMED_AREA_MOMENT_BITS);
  float qMax = pn_summedAreaPow2(PN_SUMMED_AREA_MOMENT_BITS);
  uint centre = uint(clamp(roundEven(pn_summedAreaSignedToFloat(s.xy) / m.texels), 0.0, qMax));
  uvec2 nc = pn_summedAreaMul64(uvec2(centre, 0u), n);                  // n c
  uvec2 deviation = pn_summedAreaSub64(s.xy, nc);                         // D
  uvec2 centred = pn_summedAreaSub64(s.zw, pn_summedAreaMul64(s.xy, 2u * centre));  // S2 - 2 c S1
  centred = pn_summedAreaAdd64(centred, pn_summedAreaMul64(nc, centre));             // + n c^2
  float d = pn_summedAreaSignedToFloat(deviation) / m.texels;
  m.mean = (float(centre) + d) * scale;
  m.variance = max(pn_summedAreaUnsignedToFloat(centred) / m.texels - d * d, 0.0) * (scale * scale);
  return m;
}

vec4 pn_summedAreaFloatFetch(sampler2D table, ivec2 corner) {
  PN_ON_TEXEL_FETCH();
  return texelFetch(table, corner, 0);
}

// The same from the float table of centred values v = x - 1/2: four float differences, then
// E[v^2] - E[v]^2 (the cancellation the fixed-point table avoids).
PnSummedAreaMoments pnSummedAreaRectFloatMoments(sampler2D table, ivec2 origin, ivec2 size) {
  ivec4 c = pn_summedAreaClip(textureSize(table, 0) - ivec2(1), origin, size);
  vec2 s = (pn_summedAreaFloatFetch(table, c.zw).xy - pn_summedAreaFloatFetch(table, c.zy).xy) -
           (pn_summedAreaFloatFetch(table, c.xw).xy - pn_summedAreaFloatFetch(table, c.xy).xy);
  PnSummedAreaMoments m;
  m.texels = float((c.z - c.x) * (c.w - c.y));
  if (m.texels == 0.0) {
    m.mean = 0.0;
    m.variance = 0.0;
    return m;
  }
  vec2 e = s / m.texels;
  m.mean = e.x + 0.5;
  m.variance = max(e.y - e.x * e.x, 0.0);
  return m;
}

#endif  // PENUMBRA_SUMMED_AREA_GLSL
