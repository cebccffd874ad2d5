// exports/fragment_entry.glsl — the fragment stage of every export entry (exports/X.frag): the
// call (pnExportCall of exports/X_call.glsl, which defines PN_EXPORT_CALL) in a full-screen
// triangle's fragment shader, as a deferred lighting pass makes it, the pixel from gl_FragCoord;
// the exports check holds it to the CPU's definition as it does the compute stage. Included
// after the call.

#ifdef PN_EXPORT_CALL
#include "../passes/scene_raster.h"  // PN_SCENE_TARGET_LOCATION

layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnShaded;

void main() {
  pnShaded = vec4(pnExportCall(ivec2(gl_FragCoord.xy)));
}
#else  // alone (lint): an empty compute shader
layout(local_size_x = 1) in;
void main() {}
#endif
