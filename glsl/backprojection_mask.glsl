// backprojection_mask.glsl — the light's samples as a bitmask, and which of
// them the rays from a receiver through a patch or a wall reach: the geometry
// back-projection (backprojection.glsl) builds its visibility from.
//
// description:
//   The light is side × side multi-jittered samples l in [-1/2, 1/2]² of its
//   square (backprojection.h: sample k = i · side + j lies in stratum
//   (column i, row j), in fine column k and fine row transpose(k) of the
//   side² × side² grid; its jitter a 32-bit hash of k, so GLSL and the CPU
//   reference place it on the same float). Bit k of a mask of up to 256 bits
//   (PN_BACKPROJECTION_MASK_WORDS words) is sample k. The ray from a receiver
//   to sample l crosses, at the depth whose window is W (texels; W = 0 at the
//   receiver, light_model.glsl's pnLightBlockerWindowTexels), the point
//   l · W relative to the receiver. So
//     - a patch [lo, hi] (texels, relative to the receiver) at window W
//       blocks the samples with l · W in it: l in [lo / W, hi / W], a box of
//       fine cells — whole fine columns are a range of bits, whole fine rows
//       its transpose, so the cells strictly inside are a few word operations
//       and only the four edge cells' samples are tested one by one;
//     - a wall on the line where axis a equals `edge`, between `from` and
//       `to` on the other axis, spanning windows [near, far], blocks the
//       samples whose ray meets that line at a window W = edge / l[a] in
//       [near, far] with l[1 - a] · W in [from, to]: tested one by one, only
//       the samples not yet set inside the wall's bounding box on the light.
//
// use:
//   vec2 pnBackprojectionSample(int k, int side)   light sample k of side × side (side 4, 8 or 16),
//         in [-1/2, 1/2]² of the light's square
//
// cost: a patch: side² / 32 words of two range masks each, and four samples
//   tested; a wall: the samples not yet set inside its bounding box on the
//   light, one by one (no loop in a patch: llvmpipe counts every loop
//   iteration of an invocation against one limit, backprojection.h).

#ifndef PENUMBRA_BACKPROJECTION_MASK_GLSL
#define PENUMBRA_BACKPROJECTION_MASK_GLSL

#include "backprojection.h"

// (i · side + j) -> (j · side + i): sample k's fine row, or the sample of fine row k.
int pn_backprojectionTranspose(int k, int side) {
  int shift = findMSB(side);  // side is a power of two
  return ((k & (side - 1)) << shift) + (k >> shift);
}

vec2 pnBackprojectionSample(int k, int side) {
  uint h = PN_BACKPROJECTION_HASH(uint(k));
  int bits = PN_BACKPROJECTION_JITTER_BITS;
  float unit = 1.0 / float(1 << bits);
  vec2 jitter = vec2(float(h >> uint(32 - bits)), float(h & ((1u << uint(bits)) - 1u))) * unit;
  vec2 fine = vec2(float(k), float(pn_backprojectionTranspose(k, side)));  // its fine column and row
  return (fine + jitter) * (1.0 / float(side * side)) - 0.5;
}

// Bits lo..hi of a word (0 <= lo <= hi <= 31).
uint pn_backprojectionBits(int lo, int hi) {
  uint upper = hi >= 31 ? 0xffffffffu : (1u << uint(hi + 1)) - 1u;
  return upper & ~((1u << uint(lo)) - 1u);
}

// Word w of the mask of the samples whose fine column lies in [first, last] (sample k: column k).
uint pn_backprojectionColumns(int w, int first, int last, int side) {
  int lo = max(first - 32 * w, 0), hi = min(min(last, side * side - 1) - 32 * w, 31);
  return lo > hi ? 0u : pn_backprojectionBits(lo, hi);
}

// Word w of the mask of the samples whose fine row lies in [first, last]: fine row g holds sample
// (g % side) · side + g / side, so the rows' samples are the transpose of a range — whole strata
// rows (bit j of every side-bit group) between two partial ones.
uint pn_backprojectionRows(int w, int first, int last, int side) {
  first = max(first, 0);
  last = min(last, side * side - 1);
  if (first > last) return 0u;
  int shift = findMSB(side), low = side - 1;  // side is a power of two
  int row0 = first >> shift, column0 = first & low, row1 = last >> shift, column1 = last & low;
  int base = w * (32 >> shift);  // the first stratum column in word w
  uint repeat = side == 4 ? 0x11111111u : side == 8 ? 0x01010101u : 0x00010001u;  // bit 0 of each group
  int from = clamp((column0 - base) << shift, 0, 32), to = clamp((column1 + 1 - base) << shift, 0, 32);
  uint fromMask = from >= 32 ? 0u : 0xffffffffu << uint(from);
  uint toMask = to >= 32 ? 0xffffffffu : (1u << uint(to)) - 1u;
  uint rows;
  if (row0 == row1) {
    rows = (repeat << uint(row0)) & fromMask & toMask;
  } else {
    rows = ((repeat << uint(row0)) & fromMask) | ((repeat << uint(row1)) & toMask);
    if (row1 - row0 >= 2) rows |= pn_backprojectionBits(row0 + 1, row1 - 1) * repeat;
  }
  return side * side < 32 ? rows & ((1u << uint(side * side)) - 1u) : rows;
}

// The fine cells (columns x, rows y) that [lo, hi] of the light's square [-1/2, 1/2]² touches,
// clamped to [-1, side²].
ivec4 pn_backprojectionCells(vec2 lo, vec2 hi, int side) {
  float n = float(side * side);
  vec2 a = floor(clamp((lo + 0.5) * n, -1.0, n)), b = floor(clamp((hi + 0.5) * n, -1.0, n));
  return ivec4(a, b);
}

// Sets the bit of sample k (if it is one) when l_k · window lies in [lo, hi].
void pn_backprojectSample(int k, vec2 lo, vec2 hi, float window, int side,
                          inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  if (k < 0 || k >= side * side) return;
  vec2 p = pnBackprojectionSample(k, side) * window;
  if (all(greaterThanEqual(p, lo)) && all(lessThanEqual(p, hi))) mask[k >> 5] |= 1u << uint(k & 31);
}

// Word w of the samples whose fine cells lie inside `cells` (first column, first row, last column,
// last row; inclusive), if the mask has that word.
uint pn_backprojectionBox(int w, ivec4 cells, int side) {
  if (32 * w >= side * side) return 0u;
  return pn_backprojectionColumns(w, cells.x, cells.z, side) & pn_backprojectionRows(w, cells.y, cells.w, side);
}

// Sets the bit of every sample whose ray crosses the patch [lo, hi] (texels, relative to the
// receiver) at the depth whose window is `window`: the point l · window inside the box (closed).
// The samples of the fine cells strictly inside the box in both axes are set by words (each word
// written out, not a loop: llvmpipe's limit, backprojection.h); the four on its edges (one a fine
// column or row) are tested one by one. No loop: it adds nothing to the traversal's work count.
void pn_backprojectPatch(vec2 lo, vec2 hi, float window, int side, inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  int count = side * side;
  ivec4 inside;
  if (!(window > 0.0)) {  // every ray stays on the receiver's point: every sample or none
    if (!(all(lessThanEqual(lo, vec2(0.0))) && all(greaterThanEqual(hi, vec2(0.0))))) return;
    inside = ivec4(0, 0, count - 1, count - 1);
  } else {
    ivec4 cells = pn_backprojectionCells(lo / window, hi / window, side);
    if (cells.z < 0 || cells.w < 0 || cells.x >= count || cells.y >= count) return;
    inside = cells + ivec4(1, 1, -1, -1);
    pn_backprojectSample(cells.x, lo, hi, window, side, mask);
    pn_backprojectSample(cells.z, lo, hi, window, side, mask);
    if (cells.y >= 0 && cells.y < count)
      pn_backprojectSample(pn_backprojectionTranspose(cells.y, side), lo, hi, window, side, mask);
    if (cells.w >= 0 && cells.w < count)
      pn_backprojectSample(pn_backprojectionTranspose(cells.w, side), lo, hi, window, side, mask);
  }
  mask[0] |= pn_backprojectionBox(0, inside, side);
  mask[1] |= pn_backprojectionBox(1, inside, side);
  mask[2] |= pn_backprojectionBox(2, inside, side);
  mask[3] |= pn_backprojectionBox(3, inside, side);
  mask[4] |= pn_backprojectionBox(4, inside, side);
  mask[5] |= pn_backprojectionBox(5, inside, side);
  mask[6] |= pn_backprojectionBox(6, inside, side);
  mask[7] |= pn_backprojectionBox(7, inside, side);
}

// A wall's test (pn_backprojectionWallCells) for the candidate samples of word w: each one by one.
// Returns the samples tested.
int pn_backprojectWallWord(int w, uint candidates, int a, float edge, float from, float to, float near, float far,
                           int side, inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  int b = 1 - a, tested = 0;
  for (int t = 0; t < 32 && candidates != 0u; ++t) {
    int k = 32 * w + findLSB(candidates);
    candidates &= candidates - 1u;
    ++tested;
    vec2 l = pnBackprojectionSample(k, side);
    if (l[a] == 0.0) continue;  // parallel to the wall
    float window = edge / l[a];
    float across = l[b] * window;
    if (window >= near && window <= far && across >= from && across <= to) mask[w] |= 1u << uint(k & 31);
  }
  return tested;
}

// Whether a wall on the line where axis a equals `edge`, at windows up to `far`, has samples to
// test: not on the receiver's own line (no ray crosses it there but along it), and in front of the
// receiver (far > 0).
bool pn_backprojectionWallTests(float edge, float far) {
  return edge != 0.0 && far > 0.0;
}

// The bounding box on the light (fine cells, as pn_backprojectionCells) of the samples whose ray
// crosses the wall on the line where axis `a` equals `edge`, between `from` and `to` on the other
// axis, at windows in [near, far] (the wall's depths): l[a] between edge / far and edge / near,
// l[b] = across / window between the extremes of from and to over those windows. For a wall that
// passes pn_backprojectionWallTests (far > 0, edge != 0: no division by zero); pn_backprojectWallWord
// then tests the samples not yet set inside the box, word by word, one by one (backprojection.glsl's
// walk: one loop over every wall's words).
ivec4 pn_backprojectionWallCells(int a, float edge, float from, float to, float near, float far, int side) {
  // |l| <= 1/2 for every sample: a bound past 1 (a window near 0) is the whole light.
  float la0 = edge / far, la1 = near > abs(edge) ? edge / near : sign(edge);
  vec2 lb = vec2(-1.0, 1.0);
  if (near > 0.0) {
    vec4 ends = vec4(from / near, from / far, to / near, to / far);
    lb = clamp(vec2(min(min(ends.x, ends.y), min(ends.z, ends.w)), max(max(ends.x, ends.y), max(ends.z, ends.w))),
               -1.0, 1.0);
  }
  vec2 lo = a == 0 ? vec2(min(la0, la1), lb.x) : vec2(lb.x, min(la0, la1));
  vec2 hi = a == 0 ? vec2(max(la0, la1), lb.y) : vec2(lb.y, max(la0, la1));
  return pn_backprojectionCells(lo, hi, side);
}

#endif  // PENUMBRA_BACKPROJECTION_MASK_GLSL
