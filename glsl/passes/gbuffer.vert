// gbuffer.vert — Step 2's vertex stage: world position to the camera's clip
// space; the world position goes on to the fragment stage.
// The parameter block (shared with gbuffer.frag), its binding and the locations: gbuffer.h.

#include "gbuffer.h"

layout(location = PN_SCENE_POSITION_LOCATION) in vec3 pnPosition;
layout(location = PN_GBUFFER_WORLD_LOCATION) out vec3 pnWorld;

void main() {
  pnWorld = pnPosition;
  gl_Position = pnParams.cameraViewProjection * vec4(pnPosition, 1.0);
}
