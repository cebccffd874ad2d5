// sample_table.glsl — the multi-jittered sample table and its selection rule.
//
// description:
//   Seed 000 §3.1–3.2, SPEC §4.3. The table (generated and uploaded by the
//   runner, deterministic from a seed) is a 21×8 RG32F texture of positions in
//   [0, 1)²: row = set (8 independent sets), column 0 = the 1-sample group,
//   1–4 = the 4-sample group, 5–20 = the 16-sample group; each group is
//   multi-jittered (Chiu, Shirley, Wang 1994).
//   Selection for a region of side s shaded at screen pixel (x, y):
//     Step 1  k = clamp(s / 2, 1, 4), k = floor(lb k)    -> 4^k = 1, 4 or 16 samples
//     Step 2  set n = (x + y) mod 8; columns (4^k - 1)/3 … 4(4^k - 1)/3
//     Step 3  scale each position to the region: texel = origin + floor(p * size)
//   (x, y) is the screen pixel, so neighbouring pixels use different sets (§3.1).
//
// use:
//   int   pnSampleGroupLog4(int regionSide)       k (0, 1 or 2)
//   int   pnSampleCount(int k)                    4^k
//   int   pnSampleFirstColumn(int k)              (4^k - 1) / 3
//   int   pnSampleLastColumn(int k)               4 (4^k - 1) / 3
//   int   pnSampleSet(ivec2 pixel)                (x + y) mod 8, non-negative
//   vec2  pnSample(sampler2D table, int column, int set)            (clamped into the table)
//   ivec2 pnSampleTexel(vec2 position, ivec2 origin, ivec2 size)    inside [origin, origin + size)
//
// options:
//   PN_SAMPLE_TABLE_COLUMNS 21, PN_SAMPLE_TABLE_SETS 8 (the table's layout: sample_table.h, shared
//   with the runner), PN_SAMPLE_MAX_COUNT 16 (loop bound for callers)
//
// cost: one fetch per sample.

#ifndef PENUMBRA_SAMPLE_TABLE_GLSL
#define PENUMBRA_SAMPLE_TABLE_GLSL

#include "sample_table.h"  // PN_SAMPLE_TABLE_COLUMNS, PN_SAMPLE_TABLE_SETS
#ifndef PN_SAMPLE_MAX_COUNT
#define PN_SAMPLE_MAX_COUNT 16
#endif

int pnSampleGroupLog4(int regionSide) {
  // s / 2 clamped to 1…4 and floor(lb): integer halving gives the same floor for every s >= 1
  // (a shift: the same value as s / 2 once clamped, negative sides included, without the sign fix-up).
  return findMSB(clamp(regionSide >> 1, 1, 4));
}

int pnSampleCount(int k) {
  return 1 << (2 * k);
}

int pnSampleFirstColumn(int k) {
  // (4^k - 1) / 3 = 0b0101…01 (k ones): the even bits of 4^k - 1, without an integer division.
  return (pnSampleCount(k) - 1) & 0x55555555;
}

int pnSampleLastColumn(int k) {
  return 4 * (pnSampleCount(k) - 1) / 3;
}

int pnSampleSet(ivec2 pixel) {
  return (pixel.x + pixel.y) & (PN_SAMPLE_TABLE_SETS - 1);
}

vec2 pnSample(sampler2D table, int column, int set) {
  ivec2 p = clamp(ivec2(column, set), ivec2(0), ivec2(PN_SAMPLE_TABLE_COLUMNS - 1, PN_SAMPLE_TABLE_SETS - 1));
  return texelFetch(table, p, 0).rg;
}

// pnSampleTexel with its rectangle's size as a float `scale`, read once by a caller that places many
// samples in one rectangle. The position is clamped to [0, the largest float below 1], not the
// texel to the rectangle: for any side s < 2^24, floor(p · s) <= s - 1 (the product rounds below
// s), so a table position in [0, 1) lands where it always did and any other value (NaN, ±Inf, a bad
// upload) still inside — two float clamps with constants, no register for the last texel.
vec2 pn_samplePosition(vec2 position) {
  // min(bound, x) first: NaN becomes the bound under either reading of min with a NaN.
  return max(vec2(0.0), min(vec2(uintBitsToFloat(0x3f7fffffu)), position));
}

ivec2 pn_sampleTexelIn(vec2 position, ivec2 origin, vec2 scale) {
  return origin + ivec2(floor(pn_samplePosition(position) * scale));
}

// Where a sample lands in the texels [lo, hi) when it is spread over a part of them only, [lo +
// offset, lo + offset + scale) (a square with area-weighted edges clipping them: traversal.glsl's
// pn_traversalPartOverlap), kept inside [lo, hi); offset 0 and scale hi - lo is pn_sampleTexelIn.
ivec2 pn_sampleTexelOver(vec2 position, ivec2 lo, ivec2 hi, vec2 offset, vec2 scale) {
  return lo + min(ivec2(floor(offset + pn_samplePosition(position) * scale)), hi - lo - 1);
}

ivec2 pnSampleTexel(vec2 position, ivec2 origin, ivec2 size) {
  return pn_sampleTexelIn(position, origin, vec2(max(size, ivec2(1))));
}

#endif  // PENUMBRA_SAMPLE_TABLE_GLSL
