// exports/pcf.comp — the entry `penumbra bundle pcf.glsl --target hlsl|msl` translates and the
// exports check runs: pcf_call.glsl's call in a compute shader (exports.h: why an entry).
#include "pcf_call.glsl"
#include "compute_entry.glsl"
