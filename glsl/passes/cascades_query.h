// cascades_query.h — what passes/cascades_query.comp and its runner side
// (runner/check/cascades_check.cpp) share: binding points, the query kinds
// and the parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_CASCADES_QUERY_H
#define PENUMBRA_PASSES_CASCADES_QUERY_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_CASCADES_QUERY_QUERIES_BINDING 0  // sampler2D, RGBA32F: one query a texel
#define PN_CASCADES_QUERY_RESULTS_BINDING 2  // image2D, rgba32f: its result
#define PN_CASCADES_QUERY_PARAMS_BINDING 3

// What a query asks (PnCascadesQueryParams::kind); query -> result:
#define PN_CASCADES_QUERY_SPLITS 0     // (lambda, n, f, i + 16 m) -> (practical C_i, hybrid C'_i, adaptive lambda, k_i)
#define PN_CASCADES_QUERY_SELECT 1     // (z, -, -, -) -> (index, next, nextWeight, blend of visibilities 0.1 + 0.2 c)
#define PN_CASCADES_QUERY_SPHERE 2     // (a, b, tanDiagonal, -) -> (centre depth, radius, -, -)
#define PN_CASCADES_QUERY_SNAP 3       // (x, y, texelSize, -) -> (snapped x, snapped y, -, -)

PN_UNIFORM_BLOCK(PnCascadesQueryParams, PN_CASCADES_QUERY_PARAMS_BINDING)
  vec4 splitFar;     // SELECT: C_1 ... C_m
  int kind;          // PN_CASCADES_QUERY_*
  int count;         // SELECT: m
  float near;        // SELECT: C_0
  float band;        // SELECT: the transition band
  int fadeLast;      // SELECT: 1 to fade the last cascade into lit
  float enlargement; // SPLITS: k
  float gap;         // SPLITS: g
  float pad;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_CASCADES_QUERY_H
