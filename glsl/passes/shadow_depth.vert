// shadow_depth.vert — the shadow map's vertex stage: world position to clip
// space of the light, and the linear light depth (distance along the light's
// axis, SPEC §3) for the fragment stage.
// The parameter block, its binding and the locations: shadow_depth.h.

#include "shadow_depth.h"

layout(location = PN_SCENE_POSITION_LOCATION) in vec3 pnPosition;
layout(location = PN_SHADOW_DEPTH_LINEAR_DEPTH_LOCATION) out float pnLinearDepth;

void main() {
  vec4 view = pnParams.lightView * vec4(pnPosition, 1.0);
  pnLinearDepth = -view.z;
  gl_Position = pnParams.lightProjection * view;
}
