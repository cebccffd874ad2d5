// exports/hqepcss.comp — the entry `penumbra bundle hqepcss.glsl --target hlsl|msl` translates and the
// exports check runs: hqepcss_call.glsl's call in a compute shader (exports.h: why an entry).
#include "hqepcss_call.glsl"
#include "compute_entry.glsl"
