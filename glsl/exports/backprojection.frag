// exports/backprojection.frag — backprojection_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "backprojection_call.glsl"
#include "fragment_entry.glsl"
