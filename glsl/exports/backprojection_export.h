// backprojection_export.h — the block of exports/backprojection.comp and .frag, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_BACKPROJECTION_H
#define PENUMBRA_EXPORTS_BACKPROJECTION_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

PN_UNIFORM_BLOCK(PnBackprojectionExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  int side;  // <= 0: pnBackprojectionDefaults(bias)
  float tolerance;
  int budget;
  float gap;
  float thickness;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_BACKPROJECTION_H
