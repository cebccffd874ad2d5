// backprojection_shade.frag — backprojection_shade.glsl's visibility in a fragment shader over
// a full-screen triangle (full_screen.vert), as a deferred lighting pass
// runs it (shade_pass.h; the fragment-stage check).

#include "backprojection_shade.glsl"
#include "scene_raster.h"  // PN_SCENE_TARGET_LOCATION

layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnShaded;

void main() {
  pnShaded = vec4(pnShade(ivec2(gl_FragCoord.xy)));
}
