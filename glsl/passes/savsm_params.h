// savsm_params.h — what passes/savsm_shade.comp, passes/savsm_query.comp and
// their runner side (runner/pass_runners/savsm_pass.cpp) share: binding points and
// the parameter block (the light of light_model.glsl, the table's unit range
// and savsm.glsl's settings). Valid as GLSL and as C++ (uniform_block.h).

#ifndef PENUMBRA_PASSES_SAVSM_PARAMS_H
#define PENUMBRA_PASSES_SAVSM_PARAMS_H

#include "light_fields.h"
#include "uniform_block.h"
#include "savsm.h"  // glsl/savsm.h: PN_SAVSM_TABLE_*, PN_SAVSM_BLOCKER_*

// The table kind is the pass's PN_SAVSM_TABLE (one program per kind).
// Distinct across resource kinds, so the passes are valid Vulkan GLSL as well.
#define PN_SAVSM_TABLE_BINDING 0        // usampler2D RGBA32UI (fixed) or sampler2D RG32F (float): the moments table
#define PN_SAVSM_MIP_BINDING 1          // sampler2D RGBA32F: the aligned min/max mip chain (minmax_mip.glsl)
#define PN_SAVSM_INPUT_BINDING 2        // sampler2D RGBA32F: shade, the G-buffer (u, v, depth, valid);
                                        // query, the receivers (u, v, depth, -)
#define PN_SAVSM_VISIBILITY_IMAGE 3     // shade: image2D r32f, 1 lit, 0 in shadow
#define PN_SAVSM_SEARCH_IMAGE 3         // query: image2D rgba32f, S (origin x, y, size x, y)
#define PN_SAVSM_FILTER_IMAGE 4         // query: image2D rgba32f, F (origin x, y, size x, y)
#define PN_SAVSM_BLOCKER_IMAGE 5        // query: image2D rgba32f, (blocker, has blocker, filter side, fetches)
#define PN_SAVSM_RESULT_IMAGE 6         // query: image2D rgba32f, (F's mean, variance, Chebyshev p, visibility)
#define PN_SAVSM_PARAMS_BINDING 7

PN_UNIFORM_BLOCK(PnSavsmParams, PN_SAVSM_PARAMS_BINDING)
  PN_LIGHT_FIELDS             // PnLight (light_model.glsl)
  vec2 unitRange;             // (near, 1 / (far - near)): the table's unit depth
  float bias;                 // PnSavsmSettings (savsm.glsl)
  float filterScale;
  float minVariance;
  float bleedingReduction;
  int blockerMode;
  int bound;                  // 0 or 1
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_SAVSM_PARAMS_H
