// exports/backprojection.comp — the entry `penumbra bundle backprojection.glsl --target hlsl|msl` translates and the
// exports check runs: backprojection_call.glsl's call in a compute shader (exports.h: why an entry).
#include "backprojection_call.glsl"
#include "compute_entry.glsl"
