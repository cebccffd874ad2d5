// reuse.glsl — the reuse scheme of Fast PCSS: similar neighbouring pixels
// share one representative's result.
//
// description:
//   Seed 000 §4, SPEC §4.5. Each screen pixel has an entry (d, x, y, s) of
//   the search-region map (Step 4) or filter-region map (Step 5): receiver
//   depth, region centre in shadow-map texels, region side. Two entries are
//   similar (Eq. 7) when
//     |s1 - s2| / m(s) <= sigma1,  |x1 - x2| / m(x) <= sigma2,
//     |y1 - y2| / m(y) <= sigma2,  |d1 - d2| / m(d) <= sigma3,
//   m(v) = max(|v1|, |v2|), the larger value as divisor (the paper's
//   implementation note, so that the test does not depend on the order); a
//   zero divisor means both values are 0, which compare equal. NaN never is.
//   Links stay inside k×k local regions (tiles): pixel p links to its left
//   neighbour when p.x mod k != 0 and they are similar, otherwise to its top
//   neighbour when p.y mod k != 0 and they are similar; at most one parent.
//   A pixel without a parent is a representative: it alone computes, and
//   every pixel of its group takes its result. Following parents from any
//   pixel reaches its representative in at most 2(k - 1) steps, inside the tile.
//
// use:
//   bool  pnReuseSimilar(vec4 a, vec4 b, float sigma1, float sigma2, float sigma3)   a, b = (d, x, y, s)
//   int   pnReuseParent(sampler2D entries, ivec2 p, int k, float sigma1, float sigma2, float sigma3)
//         PN_REUSE_NONE (representative), PN_REUSE_LEFT or PN_REUSE_TOP
//   ivec2 pnReuseRepresentative(sampler2D parents, ivec2 p, int k)
//         parents: the pnReuseParent codes stored as floats in .r
//   Defaults (§5.2): sigma1 = 0, sigma2 = sigma3 = 0.1; k = 4 for Step 4, 2 for Step 5.
//
// options:
//   PN_REUSE_MAX_TILE 16   largest k (loop bound of pnReuseRepresentative; reuse.h, shared with
//                          the runner like the parent codes PN_REUSE_*)
//
// cost: link: 3 fetches per pixel; representative: at most 2(k - 1) fetches.

#ifndef PENUMBRA_REUSE_GLSL
#define PENUMBRA_REUSE_GLSL

#include "reuse.h"  // PN_REUSE_MAX_TILE, PN_REUSE_NONE, PN_REUSE_LEFT, PN_REUSE_TOP

bool pn_reuseClose(float a, float b, float sigma) {
  float m = max(abs(a), abs(b));
  if (m == 0.0) return true;  // both are zero
  return abs(a - b) / m <= sigma;
}

bool pnReuseSimilar(vec4 a, vec4 b, float sigma1, float sigma2, float sigma3) {
  return pn_reuseClose(a.w, b.w, sigma1) && pn_reuseClose(a.y, b.y, sigma2) && pn_reuseClose(a.z, b.z, sigma2) &&
         pn_reuseClose(a.x, b.x, sigma3);
}

int pnReuseParent(sampler2D entries, ivec2 p, int k, float sigma1, float sigma2, float sigma3) {
  int tile = clamp(k, 1, PN_REUSE_MAX_TILE);
  ivec2 size = textureSize(entries, 0);
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) return PN_REUSE_NONE;
  vec4 e = texelFetch(entries, p, 0);
  if (p.x % tile != 0 && pnReuseSimilar(e, texelFetch(entries, p - ivec2(1, 0), 0), sigma1, sigma2, sigma3))
    return PN_REUSE_LEFT;
  if (p.y % tile != 0 && pnReuseSimilar(e, texelFetch(entries, p - ivec2(0, 1), 0), sigma1, sigma2, sigma3))
    return PN_REUSE_TOP;
  return PN_REUSE_NONE;
}

ivec2 pnReuseRepresentative(sampler2D parents, ivec2 p, int k) {
  int tile = clamp(k, 1, PN_REUSE_MAX_TILE);
  ivec2 last = textureSize(parents, 0) - ivec2(1);
  ivec2 q = clamp(p, ivec2(0), last);
  // A parent is left or above and in the same tile: 2(k - 1) steps reach the root.
  for (int step = 0; step < 2 * (PN_REUSE_MAX_TILE - 1); ++step) {
    if (step >= 2 * (tile - 1)) break;
    int parent = int(texelFetch(parents, q, 0).r);
    if (parent == PN_REUSE_LEFT && q.x % tile != 0) q.x -= 1;
    else if (parent == PN_REUSE_TOP && q.y % tile != 0) q.y -= 1;
    else break;
  }
  return q;
}

#endif  // PENUMBRA_REUSE_GLSL
