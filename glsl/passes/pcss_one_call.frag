// pcss_one_call.frag — the one-call PCSS techniques (pcss_one_call.glsl) in a
// fragment shader, as a deferred lighting pass runs them: a full-screen
// triangle (full_screen.vert) over a target the G-buffer's size, the pixel
// from gl_FragCoord. The fragment-stage check compares it with the compute pass.
//   bindings and blocks: pcss_params.h

#include "pcss_one_call.glsl"
#include "scene_raster.h"  // PN_SCENE_TARGET_LOCATION

layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnShaded;

void main() {
  float fetches;
  pnShaded = pnOneCallShade(ivec2(gl_FragCoord.xy), fetches);
}
