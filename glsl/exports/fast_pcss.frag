// exports/fast_pcss.frag — fast_pcss_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "fast_pcss_call.glsl"
#include "fragment_entry.glsl"
