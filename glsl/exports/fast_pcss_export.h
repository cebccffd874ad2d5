// fast_pcss_export.h — the block of exports/fast_pcss.comp, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_FAST_PCSS_H
#define PENUMBRA_EXPORTS_FAST_PCSS_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

// Beside exports.h's depth map: its min/max mip chain, the sample table and, with
// PN_EXPORT_SUM_TABLE defined (the check's exact case), summed_area.glsl's table of the map.
#define PN_EXPORT_SAMPLE_TABLE_BINDING 5  // sampler2D: sample_table.glsl's table
#define PN_EXPORT_SUM_TABLE_BINDING 6     // usampler2D: the map's summed-area table
#define PN_EXPORT_FAST_MIP_BINDING 7      // sampler2D: minmax_mip.glsl's chain of the map

// PnFastPcssSettings field by field (std140 in a block); filterScale <= 0: pnFastPcssDefaults(bias).
PN_UNIFORM_BLOCK(PnFastPcssExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  float filterScale;
  int refineIterations;
  int regionMode;
  int leafSide;
  int leafDivisor;
  int leafMode;
  int blockerLeafMode;
  int nodeBudget;
  int depthSums;
  int grid;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_FAST_PCSS_H
