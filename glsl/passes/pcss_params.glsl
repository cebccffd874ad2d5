// pcss_params.glsl — the uniform block every pcss_*.comp pass of the pipeline
// reads (runner/pipeline/pcss_pipeline.cpp fills it: PcssBlock).

#ifndef PENUMBRA_PCSS_PARAMS_GLSL
#define PENUMBRA_PCSS_PARAMS_GLSL

#include "light_model.glsl"

#define PN_WORK_ALL 0     // every pixel computes
#define PN_WORK_BRANCH 1  // every pixel is dispatched; non-representatives return at once
#define PN_WORK_LIST 2    // only the compacted representatives are dispatched

layout(std140, binding = 7) uniform PnPcssParams {
  float lightWidth;
  float lightNear;
  float lightNearPlaneWidth;
  float mapSize;
  float bias;
  float filterScale;    // c: filter side = c · penumbra
  int refineIterations; // 0: PCSS's search width as is
  int regionMode;       // PN_REGION_* (pcss_regions.glsl)
  int leafSide;
  int leafMode;
  int nodeBudget;
  int reuseTile;        // k; 0: no reuse
  int workMode;         // PN_WORK_*
  int bandStart;        // pcss_scan: first row of this dispatch's band
  int bandRows;
  int sampleCount;      // pcss_poisson
  float sigma1;
  float sigma2;
  float sigma3;
} pnPcss;

PnLight pnPcssLight() {
  return PnLight(pnPcss.lightWidth, pnPcss.lightNear, pnPcss.lightNearPlaneWidth, pnPcss.mapSize);
}

#endif  // PENUMBRA_PCSS_PARAMS_GLSL
