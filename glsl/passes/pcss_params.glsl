// pcss_params.glsl — the uniform block every pcss_*.comp pass of the pipeline
// reads (declared in pcss_params.h, which runner/pipeline/pcss_pipeline.cpp
// shares), and the light it describes.

#ifndef PENUMBRA_PCSS_PARAMS_GLSL
#define PENUMBRA_PCSS_PARAMS_GLSL

#include "light_model.glsl"

#include "pcss_params.h"

PnLight pnPcssLight() {
  return PnLight(pnPcss.lightWidth, pnPcss.lightNear, pnPcss.lightNearPlaneWidth, pnPcss.mapSize);
}

#endif  // PENUMBRA_PCSS_PARAMS_GLSL
