// pcss_params.glsl — the uniform block every pcss_*.comp pass of the pipeline
// reads (declared in pcss_params.h, which runner/pipeline/pcss_pipeline.cpp
// shares), and the light it describes.

#ifndef PENUMBRA_PCSS_PARAMS_GLSL
#define PENUMBRA_PCSS_PARAMS_GLSL

#include "light_model.glsl"

#include "pcss_params.h"

// The block's switches as the passes read them. The runner compiles one
// program per combination it runs (runner/gl/pass_variants.h), defining them
// as constants, so a driver that runs every side of a branch it cannot prove
// uniform runs only the taken one: on llvmpipe Step 3's pass took 31 ms at
// 1024² with both structures' searches in the program and 12 with one.
// Undefined — as lint and bundle see the passes — they follow the block.
#ifndef PN_PCSS_STRUCTURE
#define PN_PCSS_STRUCTURE (pnPcss.structure)
#endif
#ifndef PN_PCSS_REGION_MODE
#define PN_PCSS_REGION_MODE (pnPcss.regionMode)
#endif
#ifndef PN_PCSS_LEAF_MODE
#define PN_PCSS_LEAF_MODE (pnPcss.leafMode)
#endif
#ifndef PN_PCSS_DEPTH_SUMS
#define PN_PCSS_DEPTH_SUMS (pnPcss.depthSums)
#endif
#ifndef PN_PCSS_WRITE_KEYS
#define PN_PCSS_WRITE_KEYS (pnPcss.writeKeys != 0)
#endif

PnLight pnPcssLight() {
  return PN_LIGHT_FROM_FIELDS(pnPcss);
}

#endif  // PENUMBRA_PCSS_PARAMS_GLSL
