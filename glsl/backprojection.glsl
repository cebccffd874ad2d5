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
//   square, a bitmask (backprojection_mask.glsl: a patch's or a wall's
//   samples; a square of width w_L at the map's viewpoint, or the sun's
//   square of spread S). The
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
//   float pnBackprojection(sampler2D map, sampler2D mip, PnLight light, vec3 receiver, PnBackprojectionSettings s)
//         receiver = (u, v, d) as pnLightProject gives; map: the shadow map, mip: its min/max chain
//         (minmax_mip.glsl); returns the visibility in [0, 1] (1: no surface, lit)
//   PnBackprojection pnBackprojectionWork(sampler2D map, sampler2D mip, PnLight light, vec3 receiver,
//         PnBackprojectionSettings s)   the same with its work: (visibility, blocked samples,
//         nodes visited, patches that stood for nodes)
//   float pnBackprojection(sampler2D map, sampler2D mip, sampler2D secondMap, sampler2D secondMip,
//         PnLight light, vec3 receiver, PnBackprojectionSettings s)   the same over slabs: secondMap,
//         the map's second layer (its back faces), the surface behind the map's, and secondMip its chain
//   PnBackprojection pnBackprojectionWork(sampler2D map, sampler2D mip, sampler2D secondMap,
//         sampler2D secondMip, PnLight light, vec3 receiver, PnBackprojectionSettings s)   its work
//   (and backprojection_mask.glsl's pnBackprojectionSample(k, side): light sample k, in [-1/2, 1/2]²)
//
// cost: per node visited one fetch (a level-1 node four, of the map's texels), per texel four more
//   (its neighbours); per
//   patch side² / 32 mask words and four samples tested one by one; per wall
//   the samples not yet set in its box on the light, one by one. Over slabs,
//   per node two fetches, per texel or standing node eight more (both layers
//   of its neighbours), and up to two walls an edge. Bounded by `budget`
//   nodes and PN_BACKPROJECTION_MAX_WORK loop iterations (the walk is
//   stackless: no local array); what bounds it in practice is the number of
//   occluding texels whose segments reach: the penumbra's area in texels.
//
// isa budget: vgprs 64, instructions 2900, code 15616, scratch 0, loop 4450, loops 5000
//   (`penumbra isa --budgets`: both calls as an engine compiles them, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_BACKPROJECTION_GLSL
#define PENUMBRA_BACKPROJECTION_GLSL

#include "backprojection.h"
#include "backprojection_mask.glsl"  // the light samples' bitmask, patches and walls
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

// The four neighbours of node q of `level` in one layer (east, west, north, south: +x, -x, +y, -y):
// their (min, max), empty outside the map — texels from the map at level 0, nodes from the chain
// above (a level-1 neighbour's is its level-2 ancestor's: the walls of a standing level-1 node are
// estimates anyway; its exact four texels, four neighbours over two layers, cost 1,000
// instructions more over slabs): one branch a node rather than one a read.
struct PnBackprojectionNeighbours {
  vec2 east, west, north, south;
};

PnBackprojectionNeighbours pn_backprojectionNeighbours(sampler2D map, sampler2D mip, int level, ivec2 q) {
  if (level <= 0)
    return PnBackprojectionNeighbours(
        pn_mipMapNode(map, 0, q + ivec2(1, 0)), pn_mipMapNode(map, 0, q - ivec2(1, 0)),
        pn_mipMapNode(map, 0, q + ivec2(0, 1)), pn_mipMapNode(map, 0, q - ivec2(0, 1)));
  PnMipShape shape = pn_mipShape(mip);
  return PnBackprojectionNeighbours(
      pn_mipFetchOf(mip, shape, level, q + ivec2(1, 0)), pn_mipFetchOf(mip, shape, level, q - ivec2(1, 0)),
      pn_mipFetchOf(mip, shape, level, q + ivec2(0, 1)), pn_mipFetchOf(mip, shape, level, q - ivec2(0, 1)));
}

// The wall of a node on its edge toward its neighbour in one direction, whose (min, max) are
// `range` (and `back` in the second layer), as up to two pieces, each the windows (near, far) on
// the light of its bottom and its top: .xy and .zw,
// far 0 where there is none. `slab`: the node's (top, bottom); `window`: its patch's.
//   Over slabs: only the depths the neighbour's slab does not cover — from the top down to the
//   neighbour's top, and from its bottom down to the node's — since a ray that meets the union of
//   the slabs leaves it through a face no other slab covers.
//   Else (the gap rule; slab = (d, d)): toward a neighbour deeper than d (its min), down to it where
//   the surface continues into it (a step of at most gap texel widths), down to thickness · (dP - d)
//   below d at a silhouette; only what lies in front of the receiver blocks.
vec4 pn_backprojectionWallPieces(bool slabs, PnLight light, vec3 receiver, float bias, float gap, float thickness,
                                 vec2 range, vec2 back, vec2 slab, float window) {
  float dP = receiver.z;
  if (slabs) {
    vec2 neighbour = pn_backprojectionSlab(range, back, dP, bias);
    float upper = min(neighbour.x, slab.y);  // exposed from the top down to here
    float lower = max(neighbour.y, slab.x);  // and from here down to the bottom
    return vec4(upper > slab.x ? vec2(pnLightBlockerWindowTexels(light, dP, upper), window) : vec2(0.0),
                slab.y > lower ? vec2(pnLightBlockerWindowTexels(light, dP, slab.y),
                                      pnLightBlockerWindowTexels(light, dP, lower))
                               : vec2(0.0));
  }
  float d = slab.x;
  float neighbour = range.x;  // +Inf outside the map
  if (!(neighbour > d)) return vec4(0.0);
  float step = gap * pnLightTexelWorld(light, d);
  float bottom = neighbour - d <= step ? neighbour : min(neighbour, d + thickness * (dP - d));
  float deepest = min(bottom, dP - bias);
  return deepest > d ? vec4(pnLightBlockerWindowTexels(light, dP, deepest), window, 0.0, 0.0) : vec4(0.0);
}

// The edge of the node's square [lo, hi] (relative to the receiver) that direction d's wall stands on
// (d: +x, -x, +y, -y): the line where axis d >> 1 equals it.
float pn_backprojectionWallEdge(int d, vec2 lo, vec2 hi) {
  int a = d >> 1;
  float edge = (d & 1) == 0 ? hi[a] : lo[a];
  return edge;
}

// Bit 2 d + i: piece i of direction d's wall (d: +x, -x, +y, -y) has samples to test.
uint pn_backprojectionWallBits(vec4 east, vec4 west, vec4 north, vec4 south, vec2 lo, vec2 hi) {
  vec4 edges = vec4(pn_backprojectionWallEdge(0, lo, hi), pn_backprojectionWallEdge(1, lo, hi),
                    pn_backprojectionWallEdge(2, lo, hi), pn_backprojectionWallEdge(3, lo, hi));
  bvec4 first = bvec4(pn_backprojectionWallTests(edges.x, east.y), pn_backprojectionWallTests(edges.y, west.y),
                      pn_backprojectionWallTests(edges.z, north.y), pn_backprojectionWallTests(edges.w, south.y));
  bvec4 second = bvec4(pn_backprojectionWallTests(edges.x, east.w), pn_backprojectionWallTests(edges.y, west.w),
                       pn_backprojectionWallTests(edges.z, north.w), pn_backprojectionWallTests(edges.w, south.w));
  uvec4 bits = uvec4(first) | (uvec4(second) << 1u);
  return bits.x | (bits.y << 2u) | (bits.z << 4u) | (bits.w << 6u);
}

// Node q of `level` as its patch at the top of `slab` (top, bottom) and its four walls' pieces
// (pn_backprojectionWallPieces; none where the slab is flat). Exact for a texel (level 0); for a
// larger node, the estimate of what it holds. The pieces are found written out (a loop's
// iterations would count against llvmpipe's limit, backprojection.h); their samples are tested in
// one loop over every (piece, mask word), so that a GPU holds one copy of a wall's test, not four
// or eight (docs/isa.md) — the same iterations the pieces' own word loops ran. Returns the samples
// tested.
int pn_backprojectNode(sampler2D map, sampler2D mip, sampler2D secondMap, sampler2D secondMip, bool slabs,
                       PnLight light, vec3 receiver, float bias, float gap, float thickness, int level, ivec2 q,
                       vec2 slab, vec2 lo, vec2 hi, int side,
                       inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  float window = pnLightBlockerWindowTexels(light, receiver.z, slab.x);
  pn_backprojectPatch(lo, hi, window, side, mask);
  if (slabs && !(slab.y > slab.x)) return 0;
  PnBackprojectionNeighbours first = pn_backprojectionNeighbours(map, mip, level, q);
  PnBackprojectionNeighbours second = first;
  if (slabs) second = pn_backprojectionNeighbours(secondMap, secondMip, level, q);
  vec4 east = pn_backprojectionWallPieces(slabs, light, receiver, bias, gap, thickness, first.east, second.east, slab,
                                          window);
  vec4 west = pn_backprojectionWallPieces(slabs, light, receiver, bias, gap, thickness, first.west, second.west, slab,
                                          window);
  vec4 north = pn_backprojectionWallPieces(slabs, light, receiver, bias, gap, thickness, first.north, second.north,
                                           slab, window);
  vec4 south = pn_backprojectionWallPieces(slabs, light, receiver, bias, gap, thickness, first.south, second.south,
                                           slab, window);
  uint walls = pn_backprojectionWallBits(east, west, north, south, lo, hi);
  int words = (side * side + 31) / 32, w = 0, spent = 0;
  for (int i = 0; i < 8 * PN_BACKPROJECTION_MASK_WORDS && walls != 0u; ++i) {
    int piece = findLSB(walls), d = piece >> 1, a = d >> 1;
    vec4 pieces = d == 0 ? east : d == 1 ? west : d == 2 ? north : south;
    vec2 windows = (piece & 1) == 0 ? pieces.xy : pieces.zw;  // (near, far)
    float edge = pn_backprojectionWallEdge(d, lo, hi);
    ivec4 cells = pn_backprojectionWallCells(a, edge, lo[1 - a], hi[1 - a], windows.x, windows.y, side);
    spent += pn_backprojectWallWord(w, pn_backprojectionBox(w, cells, side) & ~mask[w], a, edge, lo[1 - a], hi[1 - a],
                                    windows.x, windows.y, side, mask);
    if (++w == words) {
      w = 0;
      walls &= walls - 1u;
    }
  }
  return spent;
}

// The walk of both calls: texels as the gap rule's surface (slabs false; secondMap and secondMip
// unread), or as slabs down to the second layer, secondMap with its min/max chain secondMip. A
// node's range is read exactly (pn_mipExactNode: below the chain's first level, from the map's
// texels), as when the chain held every level.
PnBackprojection pn_backprojectionWalk(sampler2D map, sampler2D mip, sampler2D secondMap, sampler2D secondMip,
                                       bool slabs, PnLight light, vec3 receiver,
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
    vec2 range = pn_mipExactNode(map, mip, node.x, node.yz);  // every node the walk visits lies in the chain
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
        vec2 back = slabs ? pn_mipExactNode(secondMap, secondMip, node.x, node.yz) : vec2(0.0);
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
          vec2 slab = slabs ? pn_backprojectionSlab(range, back, dP, bias)
                            : vec2(0.5 * (range.x + min(range.y, dP - bias)));
          work += pn_backprojectNode(map, mip, secondMap, secondMip, slabs, light, receiver, bias, s.gap, s.thickness,
                                     node.x, node.yz, slab, lo, hi, side, mask);
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

PnBackprojection pnBackprojectionWork(sampler2D map, sampler2D mip, PnLight light, vec3 receiver,
                                      PnBackprojectionSettings s) {
  return pn_backprojectionWalk(map, mip, map, mip, false, light, receiver, s);
}

PnBackprojection pnBackprojectionWork(sampler2D map, sampler2D mip, sampler2D secondMap, sampler2D secondMip,
                                      PnLight light, vec3 receiver, PnBackprojectionSettings s) {
  return pn_backprojectionWalk(map, mip, secondMap, secondMip, true, light, receiver, s);
}

float pnBackprojection(sampler2D map, sampler2D mip, PnLight light, vec3 receiver, PnBackprojectionSettings s) {
  return pnBackprojectionWork(map, mip, light, receiver, s).visibility;
}

float pnBackprojection(sampler2D map, sampler2D mip, sampler2D secondMap, sampler2D secondMip, PnLight light,
                       vec3 receiver, PnBackprojectionSettings s) {
  return pnBackprojectionWork(map, mip, secondMap, secondMip, light, receiver, s).visibility;
}

#endif  // PENUMBRA_BACKPROJECTION_GLSL
