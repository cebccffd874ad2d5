// exports/pcf.frag — pcf_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "pcf_call.glsl"
#include "fragment_entry.glsl"
