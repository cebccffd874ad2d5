// shadow_depth.frag — writes the linear light depth into an R32F target.
// Linear in view space, it is interpolated perspective-correctly, so each
// texel holds the depth of the surface point through its centre.
// Locations: shadow_depth.h.

#include "shadow_depth.h"

layout(location = PN_SHADOW_DEPTH_LINEAR_DEPTH_LOCATION) in float pnLinearDepth;
layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnDepth;

void main() {
  pnDepth = vec4(pnLinearDepth, 0.0, 0.0, 0.0);
}
