// exports/exact_pcss.comp — the entry `penumbra bundle exact_pcss.glsl --target hlsl|msl` translates and the
// exports check runs: exact_pcss_call.glsl's call in a compute shader (exports.h: why an entry).
#include "exact_pcss_call.glsl"
#include "compute_entry.glsl"
