// shadow_depth_back.frag — the shadow map's second layer from back faces
// (issue 42): the nearest surface that faces away from the light. For a mesh
// that is closed and wound counter-clockwise seen from outside (every box of
// the fixtures) it is the far side of the first solid along the light's ray,
// with no peel and no margin; for an open or inconsistently wound mesh it is
// not — which is why the module ships depth peeling (shadow_depth_peel.frag)
// and this layer is the one measured against it.
// Locations: shadow_depth.h.

#include "shadow_depth.h"

layout(location = PN_SHADOW_DEPTH_LINEAR_DEPTH_LOCATION) in float pnLinearDepth;
layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnDepth;

void main() {
  if (gl_FrontFacing) discard;
  pnDepth = vec4(pnLinearDepth, 0.0, 0.0, 0.0);
}
