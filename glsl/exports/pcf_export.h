// pcf_export.h — the block of exports/pcf.comp, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_PCF_H
#define PENUMBRA_EXPORTS_PCF_H

#include "../passes/uniform_block.h"
#include "exports.h"

PN_UNIFORM_BLOCK(PnPcfExport, PN_EXPORT_PARAMS_BINDING)
  float bias;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_PCF_H
