// poisson_pcss_export.h — the block of exports/poisson_pcss.comp and .frag, shared with the exports check
// (runner/check/exports_check.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_EXPORTS_POISSON_PCSS_H
#define PENUMBRA_EXPORTS_POISSON_PCSS_H

#include "../passes/light_fields.h"
#include "../passes/uniform_block.h"
#include "../poisson_pcss.h"
#include "exports.h"

// The two disks are constants (poisson_disks.glsl), not in the block.
PN_UNIFORM_BLOCK(PnPoissonPcssExport, PN_EXPORT_PARAMS_BINDING)
  PN_LIGHT_FIELDS
  float bias;
  float filterScale;  // <= 0: pnPoissonPcssDefaults(bias)
  int blockerSamples;
  int filterSamples;
  float rotationCos;  // the disks' rotation (cos, sin); (1, 0): none
  float rotationSin;
  float rotationAngle;     // with rotationFromAngle != 0 instead: pnPoissonRotation(rotationAngle)
  int rotationFromAngle;
PN_END_UNIFORM_BLOCK(pnExport)

#endif  // PENUMBRA_EXPORTS_POISSON_PCSS_H
