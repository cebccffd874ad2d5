// backprojection.glsl — soft shadows by back-projection over the min/max mip
// chain: the fraction of the light a receiver sees, from the shadow map read
// as a surface, not a blocker average.
//
// description:
//   Issue 28 (Guennebaud, Barthe & Paulin 2006, their gap filling; Schwarz &
//   Stamminger 2007's bitmask of light samples). The shadow map is a surface:
//   texel (i, j) at linear light depth d is a flat patch, its square at depth
//   d; two 4-neighbours whose depths differ by at most `gap` texel widths
//   (pnLightTexelWorld at the nearer one) are one surface, joined by a wall
//   on their shared edge spanning the two depths — the gap rule, closing the
//   cracks between the patches of one sloped surface; at a larger step (a
//   silhouette) the wall reaches `thickness` · (dP - d) below d (0: open;
//   1: the height field), or to the deeper neighbour if nearer — the map
//   cannot tell a box's edge over the ground from a thick occluder's side.
//   The light is side × side multi-jittered samples l in [-1/2, 1/2]² of its
//   square (backprojection.h: sample k in fine column k and fine row
//   transpose(k), so a box's samples are a few word operations; a square of
//   width w_L at the map's viewpoint, or the sun's square of spread S). The
//   ray from the receiver (u, v, dP) to sample l crosses depth z at texel
//       (u, v) + l · W(z),   W(z) = pnLightBlockerWindowTexels(light, dP, z)
//   (light_model.glsl: W(dP) = 0, growing toward the light). It is blocked
//   when it crosses a patch or a wall in front of the receiver (depth
//   < dP - bias): patch (i, j) iff l · W(d) lies in its square, a wall iff
//   the ray meets its edge's line at a window between W(its bottom) and
//   W(d), inside the edge. Each blocked sample sets its bit; overlapping
//   patches set a bit once:
//       visibility = 1 - (bits set) / side².
//   The traversal walks the aligned min/max mip chain (minmax_mip.glsl) from
//   its top, depth first, with an explicit stack:
//     - a node with min + bias >= dP cannot occlude: skipped;
//     - a node the rays cannot reach (its square outside ± W(min) / 2 around
//       the receiver) is skipped;
//     - a texel (level 0) is back-projected exactly: its patch and its walls
//       toward its deeper neighbours (four fetches);
//     - a node whose depth range is below `tolerance` · (dP - min) stands as one
//       patch at the middle of its range, with walls toward the deeper
//       neighbour nodes of its level (the texels' rule on the nodes' mins);
//       0: every node resolved to its texels;
//     - past `budget` nodes or PN_BACKPROJECTION_MAX_WORK loop iterations,
//       every node left on the stack stands as one patch likewise (an
//       estimate of what remains, never dropped).
//   With tolerance 0 and neither bound reached, the result is the fraction of
//   the same samples whose ray to the receiver crosses the map's surface —
//   exactly (runner/reference/backprojection_reference.cpp).
//   A second layer (issue 42; Bavoil, Callahan & Silva 2008) says how thick
//   each blocker is: the linear light depth d2 of the surface behind the
//   map's — the nearest back face (passes/shadow_depth_back.frag: for closed,
//   consistently wound meshes the far side of the first solid) or, by depth
//   peeling, the nearest surface behind (shadow_depth_peel.frag) — given as
//   its own min/max chain `secondMip` (minmax_mip.glsl; non-finite: +Inf).
//   Texel (i, j) is then a slab, solid from d down to d2 — its patch at d
//   and all four walls from d down to min(d2, dP - bias); +Inf: solid down
//   to the receiver; d2 <= d: the patch alone — and only the parts of its
//   walls that the neighbour's slab does not cover. A node stands as one
//   patch only when its first range is within the tolerance and its second
//   within PN_BACKPROJECTION_SECOND_LAYER_TOLERANCE times it, and then as a
//   slab from the middle of its first range to the middle of its second.
//   The gap and thickness rules serve only the call without the layer. With
//   tolerance 0 the result is the fraction of the samples whose ray meets a
//   slab — exactly (backprojection_slab_reference).
//
// use:
//   PnBackprojectionSettings { float bias; int side; float tolerance; int budget; float gap; float thickness; }
//   PnBackprojectionSettings pnBackprojectionDefaults(float bias)   side 16 (256 samples), tolerance 0.05,
//         budget PN_BACKPROJECTION_DEFAULT_BUDGET, gap 3 texel widths,
//         thickness PN_BACKPROJECTION_DEFAULT_THICKNESS
//   float pnBackprojection(sampler2D mip, PnLight light, vec3 receiver, PnBackprojectionSettings s)
//         receiver = (u, v, d) as pnLightProject gives; mip: the map's min/max chain
//         (minmax_mip.glsl); returns the visibility in [0, 1] (1: no surface, lit)
//   PnBackprojection pnBackprojectionWork(sampler2D mip, PnLight light, vec3 receiver,
//         PnBackprojectionSettings s)   the same with its work: (visibility, blocked samples,
//         nodes visited, patches that stood for nodes)
//   float pnBackprojection(sampler2D mip, sampler2D secondMip, PnLight light, vec3 receiver,
//         PnBackprojectionSettings s)   the same over slabs: secondMip, the min/max chain
//         (minmax_mip.glsl) of the map's second layer (its back faces), the surface behind the map's
//   PnBackprojection pnBackprojectionWork(sampler2D mip, sampler2D secondMip, PnLight light,
//         vec3 receiver, PnBackprojectionSettings s)   its work
//   vec2 pnBackprojectionSample(int k, int side)   light sample k, in [-1/2, 1/2]²
//
// cost: per node visited one fetch, per texel four more (its neighbours); per
//   patch side² / 32 mask words and four samples tested one by one; per wall
//   the samples not yet set in its box on the light, one by one. Over slabs,
//   per node two fetches, per texel or standing node eight more (both layers
//   of its neighbours), and up to two walls an edge. Bounded by `budget`
//   nodes and PN_BACKPROJECTION_MAX_WORK loop iterations (the walk is
//   stackless: no local array); what bounds it in practice is the number of
//   occluding texels whose segments reach: the penumbra's area in texels.
//
// isa budget: vgprs 64, instructions 4800, code 25600, scratch 0
//   (`penumbra isa --budgets`: both calls as an engine compiles them, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_BACKPROJECTION_GLSL
#define PENUMBRA_BACKPROJECTION_GLSL

#include "backprojection.h"
#include "light_model.glsl"
#include "minmax_mip.glsl"

// Nodes visited after the budget is spent: the siblings still to come, at most 3 a level.
#define PN_BACKPROJECTION_TAIL 48

struct PnBackprojectionSettings {
  float bias;       // light-depth units: a surface occludes where it is nearer than d - bias
  int side;         // samples side × side (4, 8 or 16)
  float tolerance;  // a node of depth range <= tolerance · (dP - min) is one patch; 0: texels only
  int budget;       // nodes visited before the rest stand as patches
  float gap;        // neighbours whose depths differ by <= gap texel widths are one surface (a wall joins them)
  float thickness;  // a silhouette's wall reaches thickness · (dP - d) below its top (0: open)
};

struct PnBackprojection {
  float visibility;
  float blocked;   // samples blocked
  float nodes;     // nodes visited
  float patches;   // nodes that stood as one patch (tolerance or budget)
};

PnBackprojectionSettings pnBackprojectionDefaults(float bias) {
  return PnBackprojectionSettings(bias, PN_BACKPROJECTION_DEFAULT_SIDE, PN_BACKPROJECTION_DEFAULT_TOLERANCE,
                                  PN_BACKPROJECTION_DEFAULT_BUDGET, PN_BACKPROJECTION_DEFAULT_GAP,
                                  PN_BACKPROJECTION_DEFAULT_THICKNESS);
}

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

// The wall's test (pn_backprojectWall) for the candidate samples of word w: each one by one.
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

// Sets the bit of every sample whose ray crosses the wall on the line where axis `a` equals `edge`,
// between `from` and `to` on the other axis, at windows in [near, far] (the wall's depths). Only
// the samples not yet set inside the wall's bounding box on the light are tested, one by one:
// l[a] between edge / far and edge / near, l[b] = across / window between the extremes of
// from and to over those windows. Returns the loop iterations spent (the samples tested).
int pn_backprojectWall(int a, float edge, float from, float to, float near, float far, int side,
                       inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  if (edge == 0.0 || !(far > 0.0)) return 0;
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
  ivec4 cells = pn_backprojectionCells(lo, hi, side);
  int tested = 0;
  for (int w = 0; w < (side * side + 31) / 32; ++w)
    tested += pn_backprojectWallWord(w, pn_backprojectionBox(w, cells, side) & ~mask[w], a, edge, from, to, near, far, side, mask);
  return tested;
}

// The wall of node `q` of `level` (a texel at level 0; depth d, window W(d); lo, hi: its square
// relative to the receiver) toward its neighbour node in direction `dir`, if deeper (its min): down
// to the neighbour where the surface continues into it (depth step <= gap texel widths), down to
// thickness · (dP - d) below d at a silhouette. Returns the loop iterations spent.
int pn_backprojectNodeWall(sampler2D mip, PnLight light, vec3 receiver, float bias, float gap, float thickness,
                           int level, ivec2 q, ivec2 dir, float d, float window, vec2 lo, vec2 hi, int side,
                           inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  float dP = receiver.z;
  float neighbour = pnMipFetch(mip, level, q + dir).x;  // +Inf outside the map
  if (!(neighbour > d)) return 0;
  float step = gap * pnLightTexelWorld(light, d);
  float bottom = neighbour - d <= step ? neighbour : min(neighbour, d + thickness * (dP - d));
  float deepest = min(bottom, dP - bias);  // only what lies in front of the receiver blocks
  if (!(deepest > d)) return 0;
  int a = dir.x != 0 ? 0 : 1;
  float edge = (dir[a] > 0 ? hi : lo)[a];
  return pn_backprojectWall(a, edge, lo[1 - a], hi[1 - a], pnLightBlockerWindowTexels(light, dP, deepest), window,
                            side, mask);
}

// Node `q` of `level` as one flat patch at depth d (lo, hi: its square relative to the receiver) with
// its four walls (written out, not a loop: Mesa's llvmpipe counts every loop iteration of an
// invocation against one limit, backprojection.h). Exact for a texel (level 0); for a larger node,
// the estimate of its surface. Returns the loop iterations spent (its walls').
int pn_backprojectNode(sampler2D mip, PnLight light, vec3 receiver, float bias, float gap, float thickness, int level,
                       ivec2 q, float d, vec2 lo, vec2 hi, int side, inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  float window = pnLightBlockerWindowTexels(light, receiver.z, d);
  pn_backprojectPatch(lo, hi, window, side, mask);
  int spent = pn_backprojectNodeWall(mip, light, receiver, bias, gap, thickness, level, q, ivec2(1, 0), d, window, lo, hi,
                                 side, mask);
  spent += pn_backprojectNodeWall(mip, light, receiver, bias, gap, thickness, level, q, ivec2(-1, 0), d, window, lo, hi,
                                  side, mask);
  spent += pn_backprojectNodeWall(mip, light, receiver, bias, gap, thickness, level, q, ivec2(0, 1), d, window, lo, hi,
                                  side, mask);
  spent += pn_backprojectNodeWall(mip, light, receiver, bias, gap, thickness, level, q, ivec2(0, -1), d, window, lo, hi,
                                  side, mask);
  return spent;
}

// The node after `node` in depth-first order once its subtree is done: its next sibling (children
// in the order (0,0), (1,0), (0,1), (1,1)), else its parent's next, and so on; level top + 1 when
// none is left. No loop: the levels to climb are the node's trailing (1, 1) children, the trailing
// ones of x & y (a loop here would count against llvmpipe's one limit of loop iterations an
// invocation, which the walk's own steps and walls approach on wide penumbrae).
ivec3 pn_backprojectionNext(ivec3 node, int top) {
  int climb = min(findLSB(~(node.y & node.z)), top - node.x);
  ivec3 up = ivec3(node.x + climb, node.yz >> climb);
  if (up.x >= top) return ivec3(top + 1, 0, 0);
  return (up.y & 1) == 0 ? ivec3(up.x, up.y + 1, up.z)       // (0, y) -> (1, y)
                         : ivec3(up.x, up.y - 1, up.z + 1);  // (1, 0) -> (0, 1)
}

// The slab a node stands for, clipped to what lies in front of the receiver (dP - bias):
// (top, bottom), from the (min, max) of its first layer (`range`) and of its second (`back`) — the
// middle of each (a texel: its depths); a second depth not past the top leaves it flat (bottom =
// top), +Inf makes it solid down to the receiver. (+Inf, +Inf) when none of it lies in front.
vec2 pn_backprojectionSlab(vec2 range, vec2 back, float dP, float bias) {
  if (!(range.x + bias < dP)) return vec2(pn_mipFar());
  float top = 0.5 * (range.x + min(range.y, dP - bias));
  float b = 0.5 * (back.x + back.y);
  return vec2(top, b > top ? min(b, dP - bias) : top);
}

// The wall of `slab` (top, bottom) of node q of `level` (lo, hi: its square relative to the
// receiver) on its edge toward the neighbour node in direction `dir`: only the depths the
// neighbour's slab does not cover — above the neighbour's top, below its bottom — since a ray
// that meets the union of the slabs leaves it through a face no other slab covers. Returns the
// loop iterations spent.
int pn_backprojectSlabWall(sampler2D mip, sampler2D secondMip, PnLight light, vec3 receiver, float bias, int level,
                           ivec2 q, ivec2 dir, vec2 slab, float window, vec2 lo, vec2 hi, int side,
                           inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  vec2 neighbour = pn_backprojectionSlab(pnMipFetch(mip, level, q + dir), pnMipFetch(secondMip, level, q + dir),
                                         receiver.z, bias);
  int a = dir.x != 0 ? 0 : 1, spent = 0;
  float edge = dir[a] > 0 ? hi[a] : lo[a];
  float upper = min(neighbour.x, slab.y);  // exposed from the top down to here
  if (upper > slab.x)
    spent += pn_backprojectWall(a, edge, lo[1 - a], hi[1 - a], pnLightBlockerWindowTexels(light, receiver.z, upper),
                                window, side, mask);
  float lower = max(neighbour.y, slab.x);  // and from here down to the bottom
  if (slab.y > lower)
    spent += pn_backprojectWall(a, edge, lo[1 - a], hi[1 - a], pnLightBlockerWindowTexels(light, receiver.z, slab.y),
                                pnLightBlockerWindowTexels(light, receiver.z, lower), side, mask);
  return spent;
}

// Node q of `level` as a slab (pn_backprojectionSlab of its ranges): its patch at the top and the
// exposed parts of its four walls (written out, not a loop: llvmpipe's limit, backprojection.h).
// Exact for a texel (level 0); for a larger node, the estimate of what it holds. Returns the
// loop iterations spent.
int pn_backprojectSlabNode(sampler2D mip, sampler2D secondMip, PnLight light, vec3 receiver, float bias, int level,
                           ivec2 q, vec2 range, vec2 back, vec2 lo, vec2 hi, int side,
                           inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  vec2 slab = pn_backprojectionSlab(range, back, receiver.z, bias);
  float window = pnLightBlockerWindowTexels(light, receiver.z, slab.x);
  pn_backprojectPatch(lo, hi, window, side, mask);
  if (!(slab.y > slab.x)) return 0;
  int spent = pn_backprojectSlabWall(mip, secondMip, light, receiver, bias, level, q, ivec2(1, 0), slab, window, lo, hi,
                                     side, mask);
  spent += pn_backprojectSlabWall(mip, secondMip, light, receiver, bias, level, q, ivec2(-1, 0), slab, window, lo, hi,
                                  side, mask);
  spent += pn_backprojectSlabWall(mip, secondMip, light, receiver, bias, level, q, ivec2(0, 1), slab, window, lo, hi,
                                  side, mask);
  spent += pn_backprojectSlabWall(mip, secondMip, light, receiver, bias, level, q, ivec2(0, -1), slab, window, lo, hi,
                                  side, mask);
  return spent;
}

// The walk of both calls: texels as the gap rule's surface (slabs false; secondMip unread), or as
// slabs down to the second layer, whose min/max chain secondMip is.
PnBackprojection pn_backprojectionWalk(sampler2D mip, sampler2D secondMip, bool slabs, PnLight light, vec3 receiver,
                                       PnBackprojectionSettings s) {
  float bias = s.bias;
  PnBackprojection result = PnBackprojection(1.0, 0.0, 0.0, 0.0);
  int side = clamp(s.side, PN_BACKPROJECTION_MIN_SIDE, PN_BACKPROJECTION_MAX_SIDE);
  int count = side * side;
  float dP = receiver.z;
  if (!(dP > 0.0) || isinf(dP)) return result;
  uint mask[PN_BACKPROJECTION_MASK_WORDS];
  for (int w = 0; w < PN_BACKPROJECTION_MASK_WORDS; ++w) mask[w] = 0u;
  int budget = clamp(s.budget, 1, PN_BACKPROJECTION_MAX_BUDGET);
  // Depth first over the chain without a stack (a stack of nodes in a local array is scratch
  // memory on a GPU: 36 KB a wave on RDNA 2, docs/isa.md): the next node is the first child, or the
  // next sibling of the node or of its nearest ancestor that has one (pn_backprojectionNext).
  int top = pnMipMaxLevel(mip);
  ivec3 node = ivec3(top, 0, 0);  // (level, node x, node y)
  int visited = 0, work = 0;      // nodes; loop iterations in all (PN_BACKPROJECTION_MAX_WORK)
  for (int step = 0; step < PN_BACKPROJECTION_MAX_BUDGET + PN_BACKPROJECTION_TAIL && node.x <= top; ++step) {
    vec2 range = pnMipFetch(mip, node.x, node.yz);
    ++visited;
    ++work;
    bool resolve = false;
    if (range.x + bias < dP) {  // else nothing in it can occlude (or no texel: +Inf)
      // Every patch and wall of the node lies at a depth >= its min: at most W(min) from the receiver.
      float reach = pnLightBlockerWindowTexels(light, dP, range.x);
      int size = 1 << node.x;
      vec2 lo = vec2(node.yz * size) - receiver.xy, hi = lo + float(size);
      bool within = !(any(greaterThan(lo, vec2(0.5 * reach))) || any(lessThan(hi, vec2(-0.5 * reach))));
      if (within) {
        // The second layer's (min, max) over the node (slabs); a uniform one (+Inf alike) spreads 0.
        vec2 back = slabs ? pnMipFetch(secondMip, node.x, node.yz) : vec2(0.0);
        float spread = max(range.y - range.x,
                           back.y == back.x ? 0.0 : (back.y - back.x) / PN_BACKPROJECTION_SECOND_LAYER_TOLERANCE);
        // A node is resolved unless both layers' ranges are tight (a NaN spread resolves); a texel
        // is back-projected exactly.
        resolve = node.x > 0 && visited < budget && work < PN_BACKPROJECTION_MAX_WORK &&
                  !(spread < s.tolerance * (dP - range.x));
        if (!resolve) {
          // A texel, or a node standing as one patch at the middle of its range (in front of the receiver):
          // over slabs, a slab down to the middle of its second layer's range; else with walls toward the
          // neighbour nodes deeper than it, by the texels' rule applied to the nodes' mins.
          result.patches += node.x > 0 ? 1.0 : 0.0;
          float depth = 0.5 * (range.x + min(range.y, dP - bias));
          if (slabs)
            work += pn_backprojectSlabNode(mip, secondMip, light, receiver, bias, node.x, node.yz, range, back, lo, hi,
                                           side, mask);
          else
            work += pn_backprojectNode(mip, light, receiver, bias, s.gap, s.thickness, node.x, node.yz, depth, lo, hi,
                                       side, mask);
        }
      }
    }
    node = resolve ? ivec3(node.x - 1, node.yz * 2) : pn_backprojectionNext(node, top);
  }
  int blocked = 0;
  for (int w = 0; w < PN_BACKPROJECTION_MASK_WORDS; ++w) blocked += bitCount(mask[w]);
  result.blocked = float(blocked);
  result.visibility = 1.0 - float(blocked) / float(count);
  result.nodes = float(visited);
  return result;
}

PnBackprojection pnBackprojectionWork(sampler2D mip, PnLight light, vec3 receiver, PnBackprojectionSettings s) {
  return pn_backprojectionWalk(mip, mip, false, light, receiver, s);
}

PnBackprojection pnBackprojectionWork(sampler2D mip, sampler2D secondMip, PnLight light, vec3 receiver,
                                      PnBackprojectionSettings s) {
  return pn_backprojectionWalk(mip, secondMip, true, light, receiver, s);
}

float pnBackprojection(sampler2D mip, PnLight light, vec3 receiver, PnBackprojectionSettings s) {
  return pnBackprojectionWork(mip, light, receiver, s).visibility;
}

float pnBackprojection(sampler2D mip, sampler2D secondMip, PnLight light, vec3 receiver, PnBackprojectionSettings s) {
  return pnBackprojectionWork(mip, secondMip, light, receiver, s).visibility;
}

#endif  // PENUMBRA_BACKPROJECTION_GLSL
