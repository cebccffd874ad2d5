// exports/hqepcss.frag — hqepcss_call.glsl's call in a fragment shader: the stage the exports check
// runs beside the compute entry.
#include "hqepcss_call.glsl"
#include "fragment_entry.glsl"
