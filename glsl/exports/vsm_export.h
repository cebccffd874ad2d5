// vsm_export.h — the block of exports/vsm.comp and .frag, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_VSM_H
#define PENUMBRA_EXPORTS_VSM_H

#include "../passes/uniform_block.h"
#include "exports.h"

#define PN_EXPORT_MOMENTS_BINDING 3       // sampler2D: the blurred moments (vsm.glsl)
#define PN_EXPORT_VSM_PYRAMID_BINDING 5   // sampler2DArray: the depth pyramid's first levels (the bound)
#define PN_EXPORT_VSM 0
#define PN_EXPORT_EVSM2 1
#define PN_EXPORT_EVSM4 2

PN_UNIFORM_BLOCK(PnVsmExport, PN_EXPORT_PARAMS_BINDING)
  float evsm2Exponent;
  float evsm4Positive;  // EVSM4's exponents (c+, c-)
  float evsm4Negative;
  float depthNear;      // EVSM's depth range
  float depthFar;
  float bias;
  float minVariance;
  float bleedingReduction;
  int radius;
  int kind;  // PN_EXPORT_VSM, _EVSM2 or _EVSM4
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_VSM_H
