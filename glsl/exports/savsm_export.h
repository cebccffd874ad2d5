// savsm_export.h — the block of exports/savsm.comp and .frag, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_SAVSM_H
#define PENUMBRA_EXPORTS_SAVSM_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

#define PN_EXPORT_MOMENT_TABLE_BINDING 3  // PN_SAVSM_TABLE_SAMPLER: the moments' summed-area table
#define PN_EXPORT_MIP_BINDING 5           // sampler2D: the aligned min/max mip chain (the bound)

PN_UNIFORM_BLOCK(PnSavsmExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  float filterScale;  // <= 0: pnSavsmDefaults(bias)
  float minVariance;
  float bleedingReduction;
  int blockerMode;
  int bound;          // 0 off, else on
  float unitNear;     // unitRange = (unitNear, unitScale): the table's (near, 1 / (far - near))
  float unitScale;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_SAVSM_H
