// exports/vogel_pcss.comp — the entry `penumbra bundle vogel_pcss.glsl --target hlsl|msl` translates and the
// exports check runs: vogel_pcss_call.glsl's call in a compute shader (exports.h: why an entry).
#include "vogel_pcss_call.glsl"
#include "compute_entry.glsl"
