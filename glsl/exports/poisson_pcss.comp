// exports/poisson_pcss.comp — the entry `penumbra bundle poisson_pcss.glsl --target hlsl|msl` translates and the
// exports check runs: poisson_pcss_call.glsl's call in a compute shader (exports.h: why an entry).
#include "poisson_pcss_call.glsl"
#include "compute_entry.glsl"
