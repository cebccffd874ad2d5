// backprojection_export.h — the block of exports/backprojection.comp and .frag, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_BACKPROJECTION_H
#define PENUMBRA_EXPORTS_BACKPROJECTION_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

// Beside exports.h's depth map: its min/max chain, and the second layer and its chain (the slabs' overload).
#define PN_EXPORT_SECOND_LAYER_BINDING 5  // sampler2D: the second layer's map
#define PN_EXPORT_BACKPROJECTION_MIP_BINDING 6  // sampler2D: minmax_mip.glsl's chain of the map
#define PN_EXPORT_SECOND_MIP_BINDING 7    // sampler2D: the second layer's chain

// PN_EXPORT_BACKPROJECTION_LAYERS (with PN_EXPORT_ENGINE, `penumbra isa`): 2 compiles the call over
// slabs alone, else the call without the layer.

PN_UNIFORM_BLOCK(PnBackprojectionExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  int side;  // <= 0: pnBackprojectionDefaults(bias)
  float tolerance;
  int budget;
  float gap;
  float thickness;
  int slabs;  // 1: the overload with the second layer's chain (PN_EXPORT_SECOND_LAYER_BINDING)
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_BACKPROJECTION_H
