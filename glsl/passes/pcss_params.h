// pcss_params.h — what the pipeline's pcss_*.comp passes and their runner
// side (runner/pipeline/pcss_pipeline.cpp) share: binding points, the work
// modes, the frame's parameter block and the Poisson disk's block. Valid as
// GLSL and as C++ (uniform_block.h).

#ifndef PENUMBRA_PASSES_PCSS_PARAMS_H
#define PENUMBRA_PASSES_PCSS_PARAMS_H

#include "light_fields.h"
#include "uniform_block.h"
#include "../poisson_pcss.h"
#include "../traversal.h"

// One number for one resource of a pass, whatever its kind: Vulkan (and HLSL compiled back to
// SPIR-V) has one binding namespace a descriptor set, where GL keeps texture units, image units
// and buffer bindings apart (`penumbra lint` refuses a pass that reuses a number).
// Texture units.
#define PN_PCSS_PYRAMID_BINDING 4       // sampler2DArray: the decreased pyramid (depth_pyramid.glsl)
#define PN_PCSS_GBUFFER_BINDING 5       // sampler2D: Step 2's G-buffer (pcss_search)
#define PN_PCSS_SAMPLE_TABLE_BINDING 5  // sampler2D: the multi-jittered table (pcss_traverse)
#define PN_PCSS_ENTRIES_BINDING 6       // sampler2D: the region map a pass reads, (d, x, y, s)
#define PN_PCSS_PARENTS_BINDING 8       // sampler2D: reuse parent codes (reuse.glsl)
#define PN_PCSS_RESULTS_BINDING 9       // sampler2D: the representatives' results; pcss_scan: the previous band
#define PN_PCSS_DEPTH_MAP_BINDING 10    // sampler2D: the pyramid's layer 0, the sanitized map (pcf, poisson_pcss)
#define PN_PCSS_MIP_BINDING 11          // sampler2D: the aligned min/max mip chain (minmax_mip.glsl)
#define PN_PCSS_DEPTH_SUMS_BINDING 12  // usampler2D: the summed-area table of depth (summed_area.glsl)
#define PN_PCSS_SHADE_GBUFFER_BINDING 7  // sampler2D: the G-buffer the one-call passes read (pcss_one_call.glsl)

// Image units (GLSL ES 3.1 guarantees 4: 0..3).
#define PN_PCSS_FILTER_MAP_IMAGE 0    // pcss_filter: the filter-region map
#define PN_PCSS_RECEIVER_DEPTH_IMAGE 1  // pcss_search: r32f light depth of the receiver, +Inf where no surface (Step 6's depth)
#define PN_PCSS_BLOCKER_MEAN_IMAGE 1  // pcss_filter: the blocker mean, 0 if none
#define PN_PCSS_FILTER_KEYS_IMAGE 2   // pcss_filter: what Step 5's reuse compares
#define PN_PCSS_SEARCH_MAP_IMAGE 2    // pcss_search: the search-region map
#define PN_PCSS_SEARCH_KEYS_IMAGE 3   // pcss_search: what Step 4's reuse compares
#define PN_PCSS_RESULT_IMAGE 3        // pcss_traverse, pcss_scan, pcss_poisson: per-pixel result
#define PN_PCSS_VISIBILITY_IMAGE 3    // pcss_shade, pcss_one_call: 1 − occluded fraction
#define PN_PCSS_WORK_IMAGE 2          // pcss_one_call: (visibility, Step 4's work, Step 5's work, flags)
#define PN_PCSS_FETCH_IMAGE 1         // pcss_one_call: r32f texel fetches of the call (the bench's cost proxy)

// Buffers.
#define PN_PCSS_WORK_LIST_BINDING 0     // SSBO: pcss_work.glsl's list
#define PN_PCSS_PARAMS_BINDING 13
#define PN_PCSS_POISSON_DISK_BINDING 14         // the staged Poisson passes' disk; the one call's blocker disk
#define PN_PCSS_POISSON_FILTER_DISK_BINDING 15  // the one call's PCF disk (pcss_one_call.glsl)

// How an estimating pass picks its pixels (pcss_work.glsl).
#define PN_WORK_ALL 0     // every pixel computes
#define PN_WORK_BRANCH 1  // every pixel is dispatched; non-representatives return at once
#define PN_WORK_LIST 2    // only the compacted representatives are dispatched

PN_UNIFORM_BLOCK(PnPcssParams, PN_PCSS_PARAMS_BINDING)
  PN_LIGHT_FIELDS       // PnLight (light_model.glsl)
  float bias;
  float filterScale;    // c: filter side = c · penumbra
  int refineIterations; // 0: PCSS's search width as is
  int regionMode;       // PN_REGION_* (pcss_regions.glsl)
  int leafSide;
  int leafMode;
  int nodeBudget;
  int reuseTile;        // k; 0: no reuse
  int workMode;         // PN_WORK_*
  int bandStart;        // pcss_scan: first row of this dispatch's band
  int bandRows;
  int sampleCount;      // pcss_poisson
  float sigma1;
  float sigma2;
  float sigma3;
  int structure;        // PN_STRUCTURE_* (traversal.h): what Steps 3-5 read
  int depthSums;        // pcss_traverse over the mip chain: PN_DEPTH_SUMS_* (traversal.h); NONE for Step 5
  int leafDivisor;      // pcss_traverse: > 0: the leaf side is at least the region's side / leafDivisor
  int writeKeys;        // pcss_search, pcss_filter: 0 when the reuse keys are not needed or are the entries
                        // themselves (no reuse, or the exact region mode: pnEntryLinkKey returns the entry)
  int blockerSamples;   // pcss_one_call, Poisson and Vogel: the blocker disk's samples
  int filterSamples;    // and the PCF disk's
  int blockerLeafMode;  // pcss_one_call, fast: Step 4's leaves (a PN_LEAF_*, or PN_FAST_PCSS_SAME_LEAF_MODE)
  float receiverPlaneTan;  // pcss_one_call: > 0: the receiver-plane bias from the G-buffer's neighbours,
                           // its slope clamped to this tangent (light depth per world unit across the map)
  int grid;                // pcss_traverse, pcss_one_call (fast): > 0: pnGridRegionMip with this many cells a side
PN_END_UNIFORM_BLOCK(pnPcss)

// Points in the unit disk (Bridson's, runner/sampling/poisson_disk.h), count = sampleCount.
PN_UNIFORM_BLOCK(PnPoissonDisk, PN_PCSS_POISSON_DISK_BINDING)
  PN_VEC2_ARRAY(points, PN_POISSON_MAX_SAMPLES)
PN_END_UNIFORM_BLOCK(pnDisk)

// The one-pass Poisson PCSS's PCF disk (its blocker disk is PnPoissonDisk): the same layout.
PN_UNIFORM_BLOCK(PnPoissonFilterDisk, PN_PCSS_POISSON_FILTER_DISK_BINDING)
  PN_VEC2_ARRAY(points, PN_POISSON_MAX_SAMPLES)
PN_END_UNIFORM_BLOCK(pnFilterDisk)

#include "pcss_one_call.h"  // PN_ONE_CALL_*: which call pcss_one_call.glsl makes

#endif  // PENUMBRA_PASSES_PCSS_PARAMS_H
