// exports/exact_pcss.frag — exact_pcss_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "exact_pcss_call.glsl"
#include "fragment_entry.glsl"
