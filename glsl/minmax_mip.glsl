// minmax_mip.glsl — aligned min / max mip chain of a shadow map: the
// structure Fast PCSS traverses by default (traversal.glsl,
// pnTraverseRegionMip), at 4/3 of the map's texels.
//
// description:
//   Issue 11 item 2 (b), SPEC §4.1 "beyond the paper"; issue 50 item 4 (the chain
//   from level 2: 0.17× the map). For an N×N map, P is the least power of two
//   >= max(N, 4); level i (0 <= i <= log2 P) has, for every aligned node
//   [c·2^i, (c+1)·2^i) on each axis (0 <= c < P / 2^i), the
//     (min, max) of depth over the node's texels that lie in the map
//   (+Inf, -Inf) for a node wholly outside it; depth sanitized (non-finite ->
//   +Inf, "no occluder", SPEC §3). Levels 0 and 1 are the map itself: the chain
//   keeps the levels from PN_MIP_FIRST_LEVEL (2, minmax_mip.h) up — the first
//   from the map's 4×4 texels, level i from level i-1's four children: min of
//   mins and max of maxes, exact, and the padding's identities make every
//   node's pair the min / max of exactly its texels in the map, for any N.
//   A walk reads a node below level 2 as its level-2 ancestor (a superset: a
//   decision made from it is right, an undecided node is descended or its
//   texels read from the map), and a texel's depth from the map (pnMipMapDepth).
//   Unlike the decreased pyramid (depth_pyramid.glsl: every window origin,
//   N² texels a level) only aligned nodes are kept, so a region of any
//   origin is covered by the 2×2 aligned nodes of level ceil(log2 side)
//   around it, and the traversal clips nodes to the region. No mean is kept:
//   the blocker mean's depth sums come from a summed-area table
//   (summed_area.glsl), exact over any clipped rectangle.
//
// storage:
//   sampler2D, RGBA32F, (P/8)×(P/4) with log2 P - 1 mip levels: mip level k holds node level
//   k + 2, its (P / 2^(k+2))² nodes two to a texel: texel (c, r) = (min, max) of node (2c, r) in
//   .xy and of node (2c + 1, r) in .zw (the top level's one node in .xy, (+Inf, -Inf) in .zw). No
//   channel is unused and one fetch reads a node, as a two-channel RG32F chain would — but rgba32f
//   is an image format GLSL ES 3.10 can store, rg32f is not. 8 · P²/12 bytes: 0.17× a 32-bit map
//   of side P (10.7 MiB at 4096²).
//
// use:
//   float pnMipMapDepth(sampler2D map, ivec2 p)   texel p's depth as the chain holds it (sanitized)
//   int   pnMipMaxLevel(sampler2D mip)            log2 P
//   vec2  pnMipSquareMinMax(sampler2D mip, int mapSize, ivec2 origin, int side)
//         (min, max) over a superset of the side×side square at origin, clipped
//         to the map: the union of the aligned nodes of level max(ceil(log2 side) - 1, 2)
//         it touches (at most 3×3 fetches). The min never exceeds the square's: a lit
//         decision made from it is conservative.
//   build: vec4 pnMipFirstTexel(sampler2D shadowMap, ivec2 texel)           the first level's texel
//          vec4 pnMipCombineTexel(sampler2D mip, int level, ivec2 texel)   level's texel from level - 1
//          (a level at or below PN_MIP_FIRST_LEVEL, which the map itself gives, reads as the one
//          above it: never a level outside the chain)
//
// options:
//   PN_MIP_LEVEL0_DEPTH(value)   how a texel of the map becomes linear light depth, in the build
//                                and wherever a texel is read (default: as it is); below
//
// cost: build: per texel of the first level 32 fetches of the map, per texel above
//   four fetches of the level below (log2 P - 1 dispatches); a node read:
//   1 fetch; a square: <= 9 fetches.

#ifndef PENUMBRA_MINMAX_MIP_GLSL
#define PENUMBRA_MINMAX_MIP_GLSL

#include "minmax_mip.h"

// A texel of the map as linear light depth: the map itself by default; an
// engine whose map is the light's hardware depth buffer defines it before the
// include, e.g.
//   #define PN_MIP_LEVEL0_DEPTH(value) pnLightDepthFromDepthBuffer(lightProjection, value, false)
// (light_model.glsl): the build reduces the converted depths and every texel read converts its
// own, so no linear copy of the map is made.
#ifndef PN_MIP_LEVEL0_DEPTH
#define PN_MIP_LEVEL0_DEPTH(value) (value)
#endif

// Called once per texel fetch of the chain: empty, unless a caller counts
// fetches (the savsm check's constant-cost case defines it before the include).
#ifndef PN_ON_TEXEL_FETCH
#define PN_ON_TEXEL_FETCH()
#endif

// +Inf: the depth of "no occluder"; (+Inf, -Inf) the pair of no texel.
float pn_mipFar() {
  return uintBitsToFloat(0x7f800000u);
}

vec2 pn_mipEmpty() {
  return vec2(pn_mipFar(), -pn_mipFar());
}

// The depth of the map's texel p (inside it) as the chain holds it: PN_MIP_LEVEL0_DEPTH of the
// texel, non-finite -> +Inf. What every leaf, texel and the build read.
float pnMipMapDepth(sampler2D map, ivec2 p) {
  float d = PN_MIP_LEVEL0_DEPTH(texelFetch(map, p, 0).r);
  return (isnan(d) || isinf(d)) ? pn_mipFar() : d;
}

// P: rows of the chain's first level times its node side (at least 4: a smaller map's chain is
// one node of 4×4 texels).
int pn_mipPaddedSize(sampler2D mip) {
  return textureSize(mip, 0).y << PN_MIP_FIRST_LEVEL;
}

int pnMipMaxLevel(sampler2D mip) {
  return findMSB(pn_mipPaddedSize(mip));  // P >= 4: the chain has a first level
}

// The chain's padded side P and top level, read once by a caller that reads many nodes:
// textureSize is an instruction of its own on a GPU, and the level arithmetic around it would be
// repeated at every fetch (docs/isa.md).
struct PnMipShape {
  int rows;  // P
  int top;   // pnMipMaxLevel(mip)
};

PnMipShape pn_mipShape(sampler2D mip) {
  int rows = pn_mipPaddedSize(mip);
  return PnMipShape(rows, findMSB(rows));
}

// Texel `texel` of `level` (>= PN_MIP_FIRST_LEVEL) when `wanted`: two nodes' (min, max); both
// empty outside the level or when not wanted. Without a branch: the fetch is made at a clamped
// texel and its value selected, so a GPU runs no divergent code around it (docs/isa.md);
// PN_ON_TEXEL_FETCH counts only the fetches whose value is used.
vec4 pn_mipTexelIf(sampler2D mip, PnMipShape shape, int level, ivec2 texel, bool wanted) {
  int l = clamp(level, PN_MIP_FIRST_LEVEL, shape.top);
  // The level's size from the first's: textureSize with a level that differs
  // between invocations is not computed per invocation by every driver (llvmpipe).
  int rows = shape.rows >> l;
  ivec2 size = ivec2(max(rows >> 1, 1), rows);
  bool inside = wanted && all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, size));
  if (inside) PN_ON_TEXEL_FETCH();
  vec4 t = texelFetch(mip, clamp(texel, ivec2(0), max(size - 1, ivec2(0))), l - PN_MIP_FIRST_LEVEL);
  return inside ? t : vec4(pn_mipEmpty(), pn_mipEmpty());
}

// Node `node` of a kept level (PN_MIP_FIRST_LEVEL <= level <= log2 P), inside the chain: one fetch.
vec2 pn_mipKeptNode(sampler2D mip, int level, ivec2 node) {
  vec4 t = texelFetch(mip, ivec2(node.x >> 1, node.y), level - PN_MIP_FIRST_LEVEL);
  return (node.x & 1) != 0 ? t.zw : t.xy;
}

// The node of `level` (<= log2 P) that holds texel `texel` (in the chain), bounded: its own
// (min, max) from level PN_MIP_FIRST_LEVEL up, below that its ancestor's of that level — a
// superset, so a decision made from it (all below a threshold, none below) is right for the node;
// one fetch, no branch, no bounds logic — for a walk whose nodes are inside by construction (nodes
// touching a region clipped to the map). A node the bound leaves undecided is descended, or its
// texels read from the map (pnMipMapDepth).
vec2 pn_mipNodeAt(sampler2D mip, int level, ivec2 texel) {
  int l = max(level, PN_MIP_FIRST_LEVEL);
  return pn_mipKeptNode(mip, l, texel >> l);
}

// Node `node` of `level`, bounded as pn_mipNodeAt; the empty pair outside the level.
vec2 pn_mipFetchOf(sampler2D mip, PnMipShape shape, int level, ivec2 node) {
  int l = max(level, PN_MIP_FIRST_LEVEL);
  ivec2 kept = node >> (l - level);
  int nodes = max(shape.rows >> clamp(level, 0, shape.top), 1);
  vec4 t = pn_mipTexelIf(mip, shape, l, ivec2(kept.x >> 1, kept.y), node.x < nodes);
  return (kept.x & 1) != 0 ? t.zw : t.xy;
}

// The exact (min, max) of node `node` of level 0 or 1 over its texels in the map (one or four
// fetches; a texel past the map's edge read as the edge's, which the node holds); empty outside
// the map.
vec2 pn_mipMapNode(sampler2D map, int level, ivec2 node) {
  ivec2 n = textureSize(map, 0);
  ivec2 lo = node << clamp(level, 0, 1);
  bool inside = all(greaterThanEqual(lo, ivec2(0))) && all(lessThan(lo, n));
  ivec2 hi = clamp(lo + (1 << clamp(level, 0, 1)) - 1, ivec2(0), n - 1);
  lo = clamp(lo, ivec2(0), n - 1);
  float a = pnMipMapDepth(map, lo), b = pnMipMapDepth(map, ivec2(hi.x, lo.y));
  float c = pnMipMapDepth(map, ivec2(lo.x, hi.y)), d = pnMipMapDepth(map, hi);
  return inside ? vec2(min(min(a, b), min(c, d)), max(max(a, b), max(c, d))) : pn_mipEmpty();
}

// The same for node `node` of any `level` inside the chain (0 <= node < P / 2^level): from level
// PN_MIP_FIRST_LEVEL up the chain's pair (one fetch, no bounds logic). For a walk that needs a small
// node's own range (back-projection: a node tight enough stands as one patch).
vec2 pn_mipExactNode(sampler2D map, sampler2D mip, int level, ivec2 node) {
  if (level >= PN_MIP_FIRST_LEVEL) return pn_mipKeptNode(mip, level, node);
  return pn_mipMapNode(map, level, node);
}

// The first level's node of `first` = (x, y) texels [4x, 4x + 4) × [4y, 4y + 4): the min / max
// of its texels in the map, empty in the padding.
vec2 pn_mipFirstNode(sampler2D shadowMap, ivec2 first) {
  ivec2 size = textureSize(shadowMap, 0);
  int side = 1 << PN_MIP_FIRST_LEVEL;
  ivec2 lo = first * side;
  vec2 r = pn_mipEmpty();
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      ivec2 p = lo + ivec2(x, y);
      if (any(greaterThanEqual(p, size))) continue;
      float d = pnMipMapDepth(shadowMap, p);
      r = vec2(min(r.x, d), max(r.y, d));
    }
  }
  return r;
}

vec4 pnMipFirstTexel(sampler2D shadowMap, ivec2 texel) {
  return vec4(pn_mipFirstNode(shadowMap, ivec2(2 * texel.x, texel.y)),
              pn_mipFirstNode(shadowMap, ivec2(2 * texel.x + 1, texel.y)));
}

// One node from the two texels below it that hold its four children (each texel's two nodes).
vec2 pn_mipCombineNode(vec4 upper, vec4 lower) {
  return vec2(min(min(upper.x, upper.z), min(lower.x, lower.z)), max(max(upper.y, upper.w), max(lower.y, lower.w)));
}

vec4 pn_mipTexel(sampler2D mip, int level, ivec2 texel) {
  return pn_mipTexelIf(mip, pn_mipShape(mip), level, texel, true);
}

vec4 pnMipCombineTexel(sampler2D mip, int level, ivec2 texel) {
  int below = max(level, PN_MIP_FIRST_LEVEL + 1) - 1;
  // Nodes 2c and 2c + 1 of this level: children 4c .. 4c + 3 below, texels 2c and 2c + 1 of rows 2r, 2r + 1.
  vec2 a = pn_mipCombineNode(pn_mipTexel(mip, below, ivec2(2 * texel.x, 2 * texel.y)),
                             pn_mipTexel(mip, below, ivec2(2 * texel.x, 2 * texel.y + 1)));
  vec2 b = pn_mipCombineNode(pn_mipTexel(mip, below, ivec2(2 * texel.x + 1, 2 * texel.y)),
                             pn_mipTexel(mip, below, ivec2(2 * texel.x + 1, 2 * texel.y + 1)));
  return vec4(a, b);
}

vec2 pn_mipUnion(vec2 a, vec2 b) {
  return vec2(min(a.x, b.x), max(a.y, b.y));
}

// Node first + offset of a square's cover, clamped to its last node: a node past `last` is read
// again as `last`, which the union holds already — nine fetches inside the chain, no bounds logic
// (PN_ON_TEXEL_FETCH counts the cover's nodes, not the repeats).
vec2 pn_mipSquareNode(sampler2D mip, int level, ivec2 first, ivec2 last, ivec2 offset) {
  ivec2 node = first + offset;
  if (all(lessThanEqual(node, last))) PN_ON_TEXEL_FETCH();
  return pn_mipKeptNode(mip, level, min(node, last));
}

// (min, max) over the aligned nodes that touch [lo, hi), a non-empty rectangle inside the map
// and the chain (lo < hi <= min(N, P)): pnMipSquareMinMax's cover, for a caller that clipped it.
vec2 pn_mipRectMinMax(sampler2D mip, PnMipShape shape, ivec2 lo, ivec2 hi) {
  int s = max(hi.x - lo.x, hi.y - lo.y);
  // Nodes of side 2^level >= s / 2, and of the chain's first level at least: at most 3 touch the
  // square on each axis.
  int level = min(max(findMSB(s - 1), PN_MIP_FIRST_LEVEL), shape.top);
  ivec2 first = lo >> level;
  ivec2 last = (hi - ivec2(1)) >> level;
  // The 3×3 nodes from `first`, written out, not looped (llvmpipe runs a loop's control per
  // invocation group; the fetches themselves are cheap).
  vec2 result = pn_mipSquareNode(mip, level, first, last, ivec2(0, 0));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(1, 0)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(2, 0)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(0, 1)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(1, 1)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(2, 1)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(0, 2)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(1, 2)));
  result = pn_mipUnion(result, pn_mipSquareNode(mip, level, first, last, ivec2(2, 2)));
  return result;
}

vec2 pnMipSquareMinMax(sampler2D mip, int mapSize, ivec2 origin, int side) {
  PnMipShape shape = pn_mipShape(mip);
  // The map clipped to the chain too (P >= N for the chain of an N×N map), so every node read is in it.
  int n = max(min(mapSize, shape.rows), 1);
  ivec2 lo = clamp(origin, ivec2(0), ivec2(n));
  ivec2 hi = clamp(origin + max(side, 0), lo, ivec2(n));
  if (any(greaterThanEqual(lo, hi))) return pn_mipEmpty();
  return pn_mipRectMinMax(mip, shape, lo, hi);
}

#endif  // PENUMBRA_MINMAX_MIP_GLSL
