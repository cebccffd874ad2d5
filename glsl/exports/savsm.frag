// exports/savsm.frag — savsm_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "savsm_call.glsl"
#include "fragment_entry.glsl"
