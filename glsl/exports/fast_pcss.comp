// exports/fast_pcss.comp — the entry `penumbra bundle fast_pcss.glsl --target hlsl|msl` translates and the
// exports check runs: fast_pcss_call.glsl's call in a compute shader (exports.h: why an entry).
#include "fast_pcss_call.glsl"
#include "compute_entry.glsl"
