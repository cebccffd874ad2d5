// cascade_blend.comp — a technique's visibility on cascades: each pixel takes
// the visibility of its cascade (cascades.glsl's selection by view depth)
// and, in the transition band, mixes in the next cascade's (or "lit", 1,
// past the last). Pixels that see no surface are lit. One invocation a pixel.

layout(local_size_x = 8, local_size_y = 8) in;

#include "cascade_blend.h"

layout(binding = PN_CASCADE_BLEND_VIEW_DEPTH_BINDING) uniform sampler2D pnViewDepth;
layout(binding = PN_CASCADE_BLEND_VISIBILITY0_BINDING) uniform sampler2D pnVisibility0;
layout(binding = PN_CASCADE_BLEND_VISIBILITY1_BINDING) uniform sampler2D pnVisibility1;
layout(binding = PN_CASCADE_BLEND_VISIBILITY2_BINDING) uniform sampler2D pnVisibility2;
layout(binding = PN_CASCADE_BLEND_VISIBILITY3_BINDING) uniform sampler2D pnVisibility3;
layout(r32f, binding = PN_CASCADE_BLEND_TARGET_BINDING) writeonly uniform image2D pnTarget;

#include "cascades.glsl"

// Cascade c's visibility at p; 1 (lit) for c outside [0, count).
float cascadeVisibility(int c, ivec2 p) {
  if (c < 0 || c >= pnParams.count) return 1.0;
  if (c == 0) return texelFetch(pnVisibility0, p, 0).r;
  if (c == 1) return texelFetch(pnVisibility1, p, 0).r;
  if (c == 2) return texelFetch(pnVisibility2, p, 0).r;
  return texelFetch(pnVisibility3, p, 0).r;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnTarget)))) return;
  vec4 camera = texelFetch(pnViewDepth, p, 0);
  float v = 1.0;
  if (camera.w != 0.0) {
    PnCascadeChoice c = pnCascadeSelect(camera.z, pnParams.near, pnParams.splitFar, pnParams.count, pnParams.band,
                                        pnParams.fadeLast != 0);
    v = pnCascadeBlend(cascadeVisibility(c.index, p), cascadeVisibility(c.next, p), c);
  }
  imageStore(pnTarget, p, vec4(v, 0.0, 0.0, 0.0));
}
