// exports/savsm.comp — the entry `penumbra bundle savsm.glsl --target hlsl|msl` translates and the
// exports check runs: savsm_call.glsl's call in a compute shader (exports.h: why an entry).
#include "savsm_call.glsl"
#include "compute_entry.glsl"
