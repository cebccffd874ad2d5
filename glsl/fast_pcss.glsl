// fast_pcss.glsl — Fast PCSS (Zhu et al. 2019) in one call from a lighting
// shader: the visibility of one receiver from the aligned min/max mip chain
// and the sample table, no pass of its own, no neighbour.
//
// description:
//   Steps 3 to 5 of SPEC §4.7 for one receiver, as the runner's `fast`
//   technique ships them (the staged passes pcss_search / pcss_traverse /
//   pcss_filter / pcss_shade compute the same numbers a step at a time):
//     entry   = search region of the receiver, refined `refineIterations`
//               times from the chain's min (pcss_regions.glsl); lit -> 1
//     blockers = traversal of the entry's region with depth sums
//               (traversal.glsl, pnTraverseRegionMip): mean = sum / count
//     filter  = pnFilterEntry(light, entry, mean, count > 0, filterScale)
//               (penumbra of Eq. 1 times c); no blocker -> 1
//     fraction = traversal of the filter region (counts only): occluders / texels
//     visibility = 1 - fraction
//   The region is the exact square (PN_REGION_EXACT, the default) or the
//   paper's power-of-two window (PN_REGION_WINDOW / _CENTRED). Leaves of side
//   <= leafSide are estimated from the sample table's set for `pixel`
//   (sample_table.glsl: neighbouring pixels use different sets, so the noise
//   is spatially decorrelated — a blur around the call can remove it, the
//   call itself never reads a neighbour). The work budget (issue 52): leafDivisor
//   > 0 grows the leaf with the region, leaf = max(leafSide, region side /
//   leafDivisor), and leafMode PN_LEAF_QUAD takes 4 samples a leaf of any side,
//   so a region is at most (2 leafDivisor + 1)² leaves of 4 fetches whatever
//   the light's width (0 and PN_LEAF_SAMPLED: the unbounded walk). grid > 0 bounds
//   the work instead: each region is counted over a fixed grid of about grid²
//   aligned nodes (traversal.glsl, pnGridRegionMip), ambiguous ones sampled,
//   never descended — the cost no longer grows with the penumbra.
//   Exactness: leafSide 1 with the table's depth sums (PN_TRAVERSAL_SUM_TABLE,
//   PN_DEPTH_SUMS_TABLE, PN_FAST_PCSS_ABLATIONS) and refineIterations 0 is exact
//   PCSS (brute force over the same regions) up to the rounding of the blocker
//   mean's sums.
//   The shipped settings (pnFastPcssDefaults: exact regions, quad leaves of side
//   16 and at least the region's side / 12, no node budget, the chain's midpoint
//   sums) run a walk of their own,
//   written for the GPU (docs/isa.md): the same nodes in the same order, the
//   same sums, so the same result bit for bit as traversal_mip.glsl's.
//
// use:
//   float pnFastPcss(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light, vec3 receiver, ivec2 pixel,
//                    PnFastPcssSettings settings)
//         receiver = (u, v, d): shadow-map texels (continuous) and linear light depth, as
//         pnLightProject gives (light_model.glsl); pixel = the screen pixel (gl_FragCoord.xy
//         or gl_GlobalInvocationID.xy), which picks the sample set
//   float pnFastPcss(... vec3 receiver, vec2 receiverPlane, ivec2 pixel, ...)   with a receiver-plane
//         depth bias: receiverPlane = the receiver's light depth per texel (receiver_plane.glsl, from
//         dFdx/dFdy or G-buffer neighbours); every step compares a texel with the plane at its centre and
//         decides a node against the plane's range over it (traversal.glsl); 0 is the call above
//   PnFastPcssSettings pnFastPcssDefaults(float bias)     the shipped settings (fast_pcss.h)
//   PnFastPcssResult pnFastPcssEstimate(...same parameters, either form...)   visibility and what led to it
//   map: the shadow map (linear light depth, or as PN_MIP_LEVEL0_DEPTH reads it: minmax_mip.glsl);
//   mip: minmax_mip.glsl's chain of it (RGBA32F, 0.17× the map, built per frame: pnMipFirstTexel,
//        pnMipCombineTexel); sampleTable: sample_table.glsl's 21×8 RG32F table
//        (`penumbra sample-table` prints it), all read with texelFetch only.
//
// options:
//   PN_FAST_PCSS_ABLATIONS   defined before the include: the settings' ablation fields (regionMode,
//                            leafMode min or ramp, another blockerLeafMode, nodeBudget, depthSums,
//                            grid) and leafSide 1 take effect (traversal_mip.glsl's walk, compiled in
//                            beside the shipped one). Undefined (an engine's shader): only the shipped
//                            walk is in the program; it honours bias, filterScale, refineIterations,
//                            leafSide and the work budget (leafDivisor, leafMode quad or sampled) and
//                            reads none of the ablation fields (docs/modules/fast_pcss.md)
//   PN_FAST_PCSS_LEAF_DIVISOR 12, PN_FAST_PCSS_LEAF_MODE PN_LEAF_QUAD   the defaults' work budget
//                            (fast_pcss.h): defined before the include, pnFastPcssDefaults' instead
//   PN_TRAVERSAL_SUM_TABLE   a usampler2D (summed_area.glsl's table of the map) declared before the
//                            include: settings.depthSums = PN_DEPTH_SUMS_TABLE then gives exact
//                            blocker sums (traversal.glsl; with PN_FAST_PCSS_ABLATIONS)
//   PN_AREA_EDGES 1          (the default) both regions the continuous squares with area-weighted
//                            edges (issue 51, pcss_regions.glsl's option; 0: the integer squares of
//                            whole texels: 8 VGPRs and ~40 instructions fewer): Step 3 reads the
//                            squares' covers, the walk weighs each part by its overlap, sampled leaves sit inside it, and a
//                            leaf is at most a quarter of the region's side, a region under 16 texels
//                            a side read to its texels (pnTraversalRegionLeafSide)
//   PN_TRAVERSAL_MAX_LEVEL, PN_REFINE_MAX_ITERATIONS   loop bounds (traversal.h, pcss_regions.h)
//
// cost: Step 3 <= 9 fetches a refinement; each traversal one fetch a node
//   touching the region plus 4 a quad leaf (<= 16 a sampled one: traversal.glsl),
//   at most (2 leafDivisor + 1)² leaves a region; a lit receiver stops after Step 3.
//
// isa budget: vgprs 40, instructions 700, code 4096, scratch 0, loop 400, loops 970
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md; the
//   area form, the default: PN_AREA_EDGES 0 takes 32, 656, 345 and 879 — docs/area-regions.md; the
//   work budget's per-region leaf, issue 52, added 18 cycles to the region loop of 375, none a step)

#ifndef PENUMBRA_FAST_PCSS_GLSL
#define PENUMBRA_FAST_PCSS_GLSL

#include "fast_pcss.h"
#include "light_model.glsl"
#include "minmax_mip.glsl"
#include "pcss_regions_mip.glsl"  // and pcss_regions.glsl
#include "sample_table.glsl"
#include "traversal.glsl"
#ifdef PN_FAST_PCSS_ABLATIONS  // the ablations' walks (grid, budget, leaf modes, windows, table sums)
#include "traversal_mip.glsl"
#endif

struct PnFastPcssSettings {
  float bias;            // light-depth units: a texel occludes when its depth < d - bias
  float filterScale;     // c: filter side = c · penumbra
  int refineIterations;  // Step 3's refinements, 0..PN_REFINE_MAX_ITERATIONS
  // Read by the shipped walk too: the leaf side (>= 2) and the work budget (fast_pcss.h). The rest,
  // and leafSide 1 and leafMode min or ramp, are the ablations: read only with PN_FAST_PCSS_ABLATIONS
  // (above); the shipped values otherwise.
  int regionMode;        // PN_REGION_EXACT, _WINDOW or _CENTRED (pcss_regions.h)
  int leafSide;          // >= 1
  int leafDivisor;       // leaves >= the region's side / this (the work budget); 0: off
  int leafMode;          // PN_LEAF_QUAD or _SAMPLED (the work budget); _MIN or _RAMP (traversal.h)
  int blockerLeafMode;   // Step 4's leaves: a PN_LEAF_*, or PN_FAST_PCSS_SAME_LEAF_MODE
  int nodeBudget;        // per traversal, >= 1
  int depthSums;         // Step 4: PN_DEPTH_SUMS_MIDPOINT, or _TABLE with PN_TRAVERSAL_SUM_TABLE
  int grid;              // 0: Steps 4 and 5 traverse; 1..PN_GRID_MAX_CELLS: bounded work (pnGridRegionMip)
};

struct PnFastPcssResult {
  float visibility;    // 1 - occluded fraction; 1 when lit
  vec4 searchEntry;    // Step 3's (d, x, y, s); s < 0: lit
  vec4 filterEntry;    // Step 4's (d, x, y, s); s < 0: lit
  float blockerMean;   // 0 without a blocker
  int blockerNodes;    // Step 4's traversal nodes (0 when lit after Step 3)
  int occlusionNodes;  // Step 5's (0 when lit after Step 4)
  int fetches;         // texel fetches: Step 3 at its bound (9 a refinement), the traversals' counted
};

PnFastPcssSettings pnFastPcssDefaults(float bias) {
  return PnFastPcssSettings(bias, 1.0, PN_FAST_PCSS_REFINE_ITERATIONS, PN_REGION_EXACT, PN_FAST_PCSS_LEAF_SIDE,
                            PN_FAST_PCSS_LEAF_DIVISOR, PN_FAST_PCSS_LEAF_MODE, PN_FAST_PCSS_SAME_LEAF_MODE,
                            PN_FAST_PCSS_NODE_BUDGET, PN_DEPTH_SUMS_MIDPOINT, PN_FAST_PCSS_GRID);
}

// Step 3 (pcss_regions_mip.glsl): the search entry, and its fetches at their bound (9 a refinement).
PnFastPcssResult pn_fastPcssSearch(sampler2D mip, PnLight light, vec3 receiver, vec2 receiverPlane,
                                   PnFastPcssSettings s) {
  PnFastPcssResult r = PnFastPcssResult(1.0, vec4(0.0), vec4(0.0), 0.0, 0, 0, 0);
  int refinements;
  r.searchEntry = pnSearchEntryMipPlane(mip, int(light.mapSize), light, vec4(receiver, 1.0), receiverPlane, s.bias,
                                        s.refineIterations, refinements);
  r.fetches = 9 * refinements;
  r.filterEntry = vec4(r.searchEntry.xyz, PN_REGION_LIT);
  return r;
}

// Step 4's count done: the blocker mean and the filter entry (lit: no blocker mean).
void pn_fastPcssBlockersDone(inout PnFastPcssResult r, PnTraversal blockers, PnLight light, PnFastPcssSettings s) {
  r.blockerNodes = blockers.nodes;
  r.fetches += blockers.fetches;
  r.blockerMean = pnTraversalBlockerMean(blockers);
  r.filterEntry = pnFilterEntry(light, r.searchEntry, r.blockerMean, blockers.occluders > 0.0, s.filterScale);
  if (pnEntryLit(r.filterEntry)) r.blockerMean = 0.0;
}

// Step 5's count done: the visibility.
void pn_fastPcssOcclusionDone(inout PnFastPcssResult r, PnTraversal occlusion) {
  r.occlusionNodes = occlusion.nodes;
  r.fetches += occlusion.fetches;
  r.visibility = 1.0 - pnTraversalOccludedFraction(occlusion);
}

// Whether the settings are the shipped call's (pnFastPcssDefaults, whatever the bias, filter scale,
// refinements, leaf side >= 2 and work budget): exact regions, leaves sampled (quad or the paper's)
// of one side a region, no node budget, the chain's midpoint sums, no grid — the walk below computes them.
bool pn_fastPcssShipped(PnFastPcssSettings s) {
  return s.regionMode == PN_REGION_EXACT && s.leafSide >= 2 && s.leafDivisor >= 0 && pn_traversalSamples(s.leafMode) &&
         (s.blockerLeafMode == PN_FAST_PCSS_SAME_LEAF_MODE || s.blockerLeafMode == s.leafMode) &&
         s.nodeBudget >= PN_TRAVERSAL_NO_BUDGET && s.depthSums == PN_DEPTH_SUMS_MIDPOINT && s.grid == 0;
}

// A sampled leaf's part [lo, lo + size) (traversal.glsl's PN_LEAF_SAMPLED): m samples from the
// table's column `first` of the pixel's set, each against its own texel's threshold, in order (the
// general walk's sums). One sample a run of a short loop: 57 issue cycles a sample where four
// unrolled ones cost the walk's every step. (llvmpipe counts every loop run of an invocation
// against one limit of 65,535: a 16-sample leaf is 17 runs here, 4 in the general walk — far
// below it at the sizes rendered and checked, 2048² maps at ×8 included.)
// With PN_AREA_EDGES the samples sit inside the part's overlap with the square (offset, scale:
// pn_traversalPartOverlap) and count with its area, as traversal_mip.glsl's.
void pn_fastPcssSampleLeaf(inout PnTraversal t, sampler2D map, sampler2D sampleTable, int first, int m, ivec2 lo,
                           ivec2 hi, vec2 offset, vec2 scale, PnTraversalTest test, int set) {
  float occluding = 0.0, depthSum = 0.0;
  for (int i = 0; i < m; ++i) {
    vec2 position = texelFetch(sampleTable, ivec2(first + i, set), 0).rg;
#if PN_AREA_EDGES
    ivec2 p = pn_sampleTexelOver(position, lo, hi, offset, scale);
#else
    ivec2 p = pn_sampleTexelIn(position, lo, scale);  // scale = the part's size >= 1: never empty
#endif
    float d = pnMipMapDepth(map, p);
    if (d < pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, p)) {
      occluding += 1.0;
      depthSum += d;
    }
  }
  t.fetches += m;
  pn_traversalAddSampled(t, scale.x * scale.y, occluding, depthSum, m);
}

// The shipped settings' Steps 3 to 5 (pn_fastPcssShipped): traversal_mip.glsl's walk in the same
// order with the same sums — so the same result, bit for bit — written for the wave (docs/isa.md):
// one walk body for both regions, inside a two-run loop over them (Step 4's blockers, then Step 5's
// occlusion: the switch between them outside the walk); a cursor of the node relative to the root,
// (x, y) at `level`, whose next node in Z order comes from the trailing ones of x & y (the levels
// to climb), not from a Morton code decoded each step; one chain fetch a node, without bounds
// logic (a node touching the region clipped to the map lies in the chain); leaves of the region's
// side (leafSide, or its side / leafDivisor: the work budget) sampled, nodes above it descended (no
// node budget; leaf side 1 descends to the texels, one a step, where the general walk visits a
// level-1 node's four at once).
// Step 4's midpoint sums are kept in Step 5 too, where nothing reads them.
PnFastPcssResult pn_fastPcssShippedEstimate(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light,
                                            vec3 receiver, vec2 receiverPlane, ivec2 pixel, PnFastPcssSettings s) {
  PnFastPcssResult r = pn_fastPcssSearch(mip, light, receiver, receiverPlane, s);
  // Lit after Step 3: no region. The loop's condition reads data, not a constant count alone, so
  // no compiler unrolls it into two copies of the walk (an early return would make it a constant 2
  // after it); a bool, not a count of 0 or 2, so the wave holds it as a lane mask, not in a vector
  // register through the walk (32 VGPRs in a compute shader, 40 with the count).
  bool lit = pnEntryLit(r.searchEntry);
  int n = int(light.mapSize);
  PnMipShape shape = pn_mipShape(mip);
  int chain = clamp(n, 0, shape.rows);  // the map's side inside the chain
  int leafSide = max(s.leafSide, 1);
  int set = pnSampleSet(pixel);
  PnTraversalTest test = PnTraversalTest(r.searchEntry.x - s.bias, receiverPlane, r.searchEntry.yz);
  vec4 entry = r.searchEntry;
  vec2 centre = pn_regionSquareCentre(entry.yz, max(chain, 1));  // both regions' (u, v)
  for (int region = 0; region < 2 && !lit; ++region) {  // Step 4, then Step 5
    // The region inside the map and the chain (pn_traversalBegin's clip: the square is inside
    // [0, chain) already, but for the largest root's side), and its texels.
#if PN_AREA_EDGES
    PnArea area = pn_regionAreaAbout(centre, entry.w, max(chain, 1));  // pnEntryArea
    PnRect square = area.cover;
#else
    PnRect square = pn_regionSquareAbout(centre, entry.w, max(chain, 1));  // pnEntryRect
#endif
    ivec2 start = square.origin;
    ivec2 size = chain > 0 ? min(square.size, ivec2(1 << PN_TRAVERSAL_MAX_LEVEL)) : ivec2(0);
    ivec2 end = start + size;
#if PN_AREA_EDGES
    area.hi = min(area.hi, vec2(end));  // the largest root's clip (pn_traversalBeginArea)
    PnTraversal t = PnTraversal(0.0, 0.0, pnRegionAreaOver(area, start, end), 0, 0);
#else
    PnTraversal t = PnTraversal(0.0, 0.0, float(size.x) * float(size.y), 0, 0);
#endif
    // The 2×2 aligned nodes of level `top` at the region's aligned corner cover it; they are the
    // children of a virtual root at level top + 1, never read.
    int top = min(findMSB(max(size.x, size.y) - 1) + 1, shape.top);
    ivec2 rootOrigin = (start >> top) << top;
    int level = top;
    ivec2 node = ivec2(0);
    // Nodes of side > leafSide descend, so every leaf of the region is of one level: its sample
    // group is the region's (sample_table.glsl), not a leaf's.
    // The leaf for the region: at least its longer side / leafDivisor (the work budget, fast_pcss.h;
    // 0: leafSide); with PN_AREA_EDGES at most a quarter of its side, and 1 — its texels, one
    // sample each — where that is under 4 (pnTraversalRegionLeafSide).
#if PN_AREA_EDGES
    int regionLeaf = pnTraversalRegionLeafSide(leafSide, s.leafDivisor, size);
#else
    int regionLeaf = pnTraversalLeafSide(leafSide, s.leafDivisor, size);
#endif
    int leafLevel = min(top, findMSB(regionLeaf));  // nodes above it descend
    int k = pnSampleGroupLog4(pn_traversalSampleSide(s.leafMode, 1 << leafLevel));
    int m = pnSampleCount(k), first = pnSampleFirstColumn(k);
    bool empty = isnan(test.threshold) || t.texels == 0.0;
    for (int it = 0; it < PN_TRAVERSAL_CURSOR_STEPS && !empty; ++it) {
      ivec2 origin = rootOrigin + (node << level);
#if PN_AREA_EDGES
      // The part from the square's float corners: its overlap [from, to) and the texels it touches
      // [lo, hi) — the cover's clip of the node exactly (the cover is [floor(lo), ceil(hi))), without
      // the cover held through the walk (8 VGPRs fewer).
      vec2 from = max(vec2(origin), area.lo), to = min(vec2(origin + (1 << level)), area.hi);
      ivec2 lo = ivec2(floor(from)), hi = ivec2(ceil(to));
#else
      ivec2 lo = max(origin, start), hi = min(origin + (1 << level), end);
#endif
      t.nodes += 1;
      bool descend = false;
      if (all(lessThan(lo, hi))) {
        vec2 depths = pn_mipNodeAt(mip, level, origin);
        t.fetches += 1;
        vec2 threshold = pnReceiverPlaneThresholdRange(test.threshold, test.gradient, test.centre, lo, hi);
#if PN_AREA_EDGES
        vec2 offset = from - vec2(lo), scale = to - from;  // the overlap, as pn_traversalPartOverlap's
#else
        // The part's texels as float(x · y) rounds them (x, y < 2^24: the product of two exact
        // floats, rounded once), without a quarter-rate integer multiply.
        vec2 offset = vec2(0.0), scale = vec2(hi - lo);
#endif
        if (depths.y < threshold.x) {  // every texel occludes: its midpoint sum (exact when flat)
          float texels = scale.x * scale.y;
          t.occluders += texels;
          t.depthSum += (depths.x == depths.y ? depths.x : 0.5 * (depths.x + depths.y)) * texels;
        } else if (depths.x < threshold.y) {  // ambiguous
          descend = level > leafLevel;
          if (!descend) pn_fastPcssSampleLeaf(t, map, sampleTable, first, m, lo, hi, offset, scale, test, set);
        }
      }
      if (pn_traversalCursorNext(node, level, descend, top)) break;  // the virtual root's last child done
    }
    if (region == 1) {
      pn_fastPcssOcclusionDone(r, t);
      break;
    }
    pn_fastPcssBlockersDone(r, t, light, s);
    if (pnEntryLit(r.filterEntry)) break;
    entry = r.filterEntry;
  }
  return r;
}

#ifdef PN_FAST_PCSS_ABLATIONS
// The bounded-work ablation's count of an entry's region (settings.grid > 0): pnGridRegionMip's
// grid (Step 4 with depth sums, Step 5 without).
PnTraversal pn_fastPcssGrid(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize, vec4 entry,
                            vec2 receiverPlane, PnFastPcssSettings s, int leafMode, int depthSums, ivec2 pixel) {
  return pn_gridAreaMip(map, mip, sampleTable, mapSize, pnEntryArea(entry, mapSize, s.regionMode), entry.yzx,
                        receiverPlane, s.bias, s.grid, s.leafSide, leafMode, depthSums, pixel);
}

// The walk of an entry's region over the chain, one node a step; its leaf side in `leafSide`.
PnTraversalWalk pn_fastPcssWalk(PnMipShape shape, int mapSize, vec4 entry, PnTraversalTest test, PnFastPcssSettings s,
                                out int leafSide) {
  PnArea region = pnEntryArea(entry, mapSize, s.regionMode);
#if PN_AREA_EDGES
  leafSide = pnTraversalRegionLeafSide(s.leafSide, s.leafDivisor, region.cover.size);
#else
  leafSide = pnTraversalLeafSide(s.leafSide, s.leafDivisor, region.cover.size);
#endif
  return pn_traversalWalkBegin(shape, mapSize, region, test, pn_traversalBudget(s.nodeBudget));
}

// Any settings (PN_FAST_PCSS_ABLATIONS): traversal_mip.glsl's walk, with its budget, leaf modes,
// windows and table sums, or the grid.
PnFastPcssResult pn_fastPcssAblationsEstimate(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light,
                                              vec3 receiver, vec2 receiverPlane, ivec2 pixel, PnFastPcssSettings s) {
  int n = int(light.mapSize);
  PnFastPcssResult r = pn_fastPcssSearch(mip, light, receiver, receiverPlane, s);
  if (pnEntryLit(r.searchEntry)) return r;

  int blockerLeafMode = s.blockerLeafMode == PN_FAST_PCSS_SAME_LEAF_MODE ? s.leafMode : s.blockerLeafMode;
  if (s.grid > 0) {  // the bounded-work ablation: two grid passes
    PnTraversal blockers = pn_fastPcssGrid(map, mip, sampleTable, n, r.searchEntry, receiverPlane, s, blockerLeafMode,
                                           s.depthSums, pixel);
    pn_fastPcssBlockersDone(r, blockers, light, s);
    if (pnEntryLit(r.filterEntry)) return r;
    pn_fastPcssOcclusionDone(r, pn_fastPcssGrid(map, mip, sampleTable, n, r.filterEntry, receiverPlane, s, s.leafMode,
                                              PN_DEPTH_SUMS_NONE, pixel));
    return r;
  }
  // Step 4 (the blockers, with depth sums) then Step 5 (the occlusion, without) as one loop over
  // two walks of the chain: one traversal body in the program, not two inlined copies — half the
  // code and registers on a GPU (docs/isa.md). Each walk gets its own iterations, as alone.
  // Both regions are tested against one receiver (the filter entry keeps the search entry's
  // (d, u, v)): one test for both walks.
  PnMipShape shape = pn_mipShape(mip);
  PnTraversalTest test = PnTraversalTest(r.searchEntry.x - s.bias, receiverPlane, r.searchEntry.yz);
  int budget = pn_traversalBudget(s.nodeBudget);
  int leafSide;
  PnTraversalWalk w = pn_fastPcssWalk(shape, n, r.searchEntry, test, s, leafSide);
  bool blockers = true;
  int limit = max(w.iterations, 1);
  for (int it = 0; it < limit; ++it) {
    pn_traversalWalkStep(w, map, mip, shape, sampleTable, test, leafSide, blockers ? blockerLeafMode : s.leafMode,
                         budget, blockers ? s.depthSums : PN_DEPTH_SUMS_NONE, pixel);
    if (!w.done && it + 1 < limit) continue;
    if (!blockers) {  // Step 5 is over
      pn_fastPcssOcclusionDone(r, w.r);
      break;
    }
    pn_fastPcssBlockersDone(r, w.r, light, s);
    if (pnEntryLit(r.filterEntry)) break;
    blockers = false;
    w = pn_fastPcssWalk(shape, n, r.filterEntry, test, s, leafSide);
    limit = it + 1 + max(w.iterations, 1);
  }
  return r;
}

#endif  // PN_FAST_PCSS_ABLATIONS

PnFastPcssResult pnFastPcssEstimate(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light, vec3 receiver,
                                    vec2 receiverPlane, ivec2 pixel, PnFastPcssSettings s) {
#ifdef PN_FAST_PCSS_ABLATIONS
  if (!pn_fastPcssShipped(s))
    return pn_fastPcssAblationsEstimate(map, mip, sampleTable, light, receiver, receiverPlane, pixel, s);
#endif
  return pn_fastPcssShippedEstimate(map, mip, sampleTable, light, receiver, receiverPlane, pixel, s);
}

PnFastPcssResult pnFastPcssEstimate(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light, vec3 receiver,
                                    ivec2 pixel, PnFastPcssSettings s) {
  return pnFastPcssEstimate(map, mip, sampleTable, light, receiver, vec2(0.0), pixel, s);
}

float pnFastPcss(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light, vec3 receiver, vec2 receiverPlane,
                 ivec2 pixel, PnFastPcssSettings settings) {
  return pnFastPcssEstimate(map, mip, sampleTable, light, receiver, receiverPlane, pixel, settings).visibility;
}

float pnFastPcss(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light, vec3 receiver, ivec2 pixel,
                 PnFastPcssSettings settings) {
  return pnFastPcssEstimate(map, mip, sampleTable, light, receiver, pixel, settings).visibility;
}

#endif  // PENUMBRA_FAST_PCSS_GLSL
