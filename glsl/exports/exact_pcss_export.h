// exact_pcss_export.h — the block of exports/exact_pcss.comp, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_EXACT_PCSS_H
#define PENUMBRA_EXPORTS_EXACT_PCSS_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

PN_UNIFORM_BLOCK(PnExactPcssExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  float filterScale;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_EXACT_PCSS_H
