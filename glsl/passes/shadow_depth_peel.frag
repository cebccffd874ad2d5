// shadow_depth_peel.frag — the shadow map's second layer by depth peeling
// (issue 42; Everitt 2001, as Bavoil, Callahan & Silva 2008 use it): the
// nearest surface behind the first layer, the map. A fragment no deeper than
// the map's texel (beyond PN_SHADOW_DEPTH_PEEL_MARGIN) is dropped; the depth
// test keeps the nearest of the rest. For a closed mesh that is the far side
// of the first solid along the light's ray: the blocker's thickness.
// Locations and bindings: shadow_depth.h.

#include "shadow_depth.h"

layout(binding = PN_SHADOW_DEPTH_FIRST_LAYER_BINDING) uniform sampler2D pnFirstLayer;
layout(location = PN_SHADOW_DEPTH_LINEAR_DEPTH_LOCATION) in float pnLinearDepth;
layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnDepth;

void main() {
  // The framebuffer's texel is the map's texel: both are drawn through the same light.
  float first = texelFetch(pnFirstLayer, ivec2(gl_FragCoord.xy), 0).x;
  if (!(pnLinearDepth > first + PN_SHADOW_DEPTH_PEEL_MARGIN * abs(first))) discard;
  pnDepth = vec4(pnLinearDepth, 0.0, 0.0, 0.0);
}
