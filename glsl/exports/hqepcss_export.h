// hqepcss_export.h — the block of exports/hqepcss.comp, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_HQEPCSS_H
#define PENUMBRA_EXPORTS_HQEPCSS_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

// Besides exports.h's depth map: the decreased depth pyramid of the map.
#define PN_EXPORT_PYRAMID_BINDING 5  // sampler2DArray: depth_pyramid.glsl's levels

// PnHqepcssSettings field by field (std140 in a block); filterScale <= 0: pnHqepcssDefaults(bias).
PN_UNIFORM_BLOCK(PnHqepcssExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  float filterScale;
  int refineIterations;
  int regionMode;
  int leafSide;
  int leafDivisor;
  int nodeBudget;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_HQEPCSS_H
