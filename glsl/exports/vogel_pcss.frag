// exports/vogel_pcss.frag — vogel_pcss_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "vogel_pcss_call.glsl"
#include "fragment_entry.glsl"
