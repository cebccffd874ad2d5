// exports/poisson_pcss.frag — poisson_pcss_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "poisson_pcss_call.glsl"
#include "fragment_entry.glsl"
