// savsm_params.glsl — the light and the settings of savsm.glsl from the
// savsm passes' parameter block (savsm_params.h), for savsm_shade.comp and
// savsm_query.comp.

#ifndef PENUMBRA_PASSES_SAVSM_PARAMS_GLSL
#define PENUMBRA_PASSES_SAVSM_PARAMS_GLSL

#include "savsm_params.h"
#include "savsm.glsl"

PnLight pnSavsmParamsLight() {
  return PN_LIGHT_FROM_FIELDS(pnParams);
}

PnSavsmSettings pnSavsmParamsSettings() {
  return PnSavsmSettings(pnParams.bias, pnParams.filterScale, pnParams.minVariance, pnParams.bleedingReduction,
                         pnParams.blockerMode, pnParams.bound != 0);
}

#endif  // PENUMBRA_PASSES_SAVSM_PARAMS_GLSL
