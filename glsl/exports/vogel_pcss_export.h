// vogel_pcss_export.h — the block of exports/vogel_pcss.comp and .frag, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_VOGEL_PCSS_H
#define PENUMBRA_EXPORTS_VOGEL_PCSS_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "exports.h"

PN_UNIFORM_BLOCK(PnVogelPcssExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  float filterScale;  // <= 0: pnVogelPcssDefaults(bias)
  int blockerSamples;
  int filterSamples;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_VOGEL_PCSS_H
