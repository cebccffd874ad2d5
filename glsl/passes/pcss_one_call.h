// pcss_one_call.h — which call pcss_one_call.glsl makes (PN_PCSS_ONE_CALL, a compile-time
// switch): shared with the pipeline (runner/pipeline/pcss_pipeline.cpp) and `penumbra isa`
// (runner/isa/isa_entries.cpp). Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_PCSS_ONE_CALL_H
#define PENUMBRA_PASSES_PCSS_ONE_CALL_H

#define PN_ONE_CALL_FAST 0     // pnFastPcss (fast_pcss.glsl)
#define PN_ONE_CALL_POISSON 1  // pnPoissonPcss (poisson_pcss.glsl)
#define PN_ONE_CALL_EXACT 2    // pnExactPcss (exact_pcss.glsl)
#define PN_ONE_CALL_HQEPCSS 3  // pnHqepcss (hqepcss.glsl)
#define PN_ONE_CALL_VOGEL 4    // pnVogelPcss (vogel_pcss.glsl)

#endif  // PENUMBRA_PASSES_PCSS_ONE_CALL_H
