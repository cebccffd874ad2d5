// exports/vsm.comp — the entry `penumbra bundle vsm.glsl --target hlsl|msl` translates and the
// exports check runs: vsm_call.glsl's call in a compute shader (exports.h: why an entry).
#include "vsm_call.glsl"
#include "compute_entry.glsl"
