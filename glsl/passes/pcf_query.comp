// pcf_query.comp — pcf.glsl over a batch of windows.
// Query k: texel k of query image A = (window origin x, y, width, height),
//          texel k of query image B = (receiver depth, bias, band rows, 0).
//   band rows 0: one pnPcfWindow call; band rows b > 0: bands of b rows from
//   row 0 of the map to its last, added up with pnPcfAddRows (what
//   pcss_scan.comp does across dispatches, here in one invocation).
// Result k: (occluders, depth sum, texels, 0).
// B.w = 1 instead: pnPcfBilinearVisibility at position A.xy for receiver B.x, bias B.y (at odd
//   texel columns the one call pnPcf(depthMap, (A.xy, B.x), bias), the same by definition); result
//   (visibility, 0, 0, 0); with a receiver-plane gradient A.zw != 0, pnPcf's plane overload
//   (pnPcfBilinearVisibilityPlane at (A.xy, B.x)).
// B.w = 2 instead: the area-weighted window (issue 51) of pnRegionArea(A.xy, A.z, map width):
//   band rows 0 pnPcfAreaPlane (flat plane), b > 0 bands of b rows added up with
//   pnPcfAddAreaRowsPlane; result (occluders, depth sum, texels, r) as areas, r = pnPcfBlockerMean at
//   odd columns, pnPcfOccludedFraction at even ones (fractional counts: the weights' own test).
// B.w = 3 / 4 instead: the window (A as for B.w = 0) / the area-weighted square (A as for B.w = 2)
//   with a receiver plane of gradient C.xy about (C.zw, B.x) / (A.xy, B.x): band rows 0
//   pnPcfWindowPlane / pnPcfAreaPlane, b > 0 bands of b rows added up with pnPcfAddRowsPlane /
//   pnPcfAddAreaRowsPlane; result (occluders, depth sum, texels, 0 / the ratio as for B.w = 2).
//   bindings: pcf_query.h
// The check also compiles it with a small PN_PCF_MAX_SIDE to exercise the bound.

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcf_query.h"

layout(binding = PN_PCF_QUERY_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_PCF_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_PCF_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(binding = PN_PCF_QUERY_C_BINDING) uniform sampler2D pnQueryC;
layout(rgba32f, binding = PN_PCF_QUERY_RESULT_IMAGE) writeonly uniform image2D pnResult;

#include "pcf.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  ivec2 origin = ivec2(a.xy), size = ivec2(a.zw);
  if (b.w == 1.0) {
    // Without a gradient, every other query through the one call pnPcf(depthMap, receiver, bias).
    float v = !all(equal(a.zw, vec2(0.0))) ? pnPcf(pnDepthMap, vec3(a.xy, b.x), a.zw, b.y)
              : (p.x % 2 == 1)             ? pnPcf(pnDepthMap, vec3(a.xy, b.x), b.y)
                                           : pnPcfBilinearVisibility(pnDepthMap, a.xy, b.x, b.y);
    imageStore(pnResult, p, vec4(v, 0.0, 0.0, 0.0));
    return;
  }
  int rows = int(b.z);
  if (b.w == 3.0 || b.w == 4.0) {
    vec4 c = texelFetch(pnQueryC, p, 0);
    bool area = b.w == 4.0;
    PnArea square = pnRegionArea(a.xy, a.z, textureSize(pnDepthMap, 0).x);
    vec3 receiver = area ? vec3(a.xy, b.x) : vec3(c.zw, b.x);
    PnPcf s = pnPcfZero();
    if (rows <= 0) {
      s = area ? pnPcfAreaPlane(pnDepthMap, square, receiver, c.xy, b.y)
               : pnPcfWindowPlane(pnDepthMap, origin, size, receiver, c.xy, b.y);
    } else {
      int height = textureSize(pnDepthMap, 0).y;
      for (int first = 0; first < height; first += rows)
        s = area ? pnPcfAddAreaRowsPlane(pnDepthMap, square, receiver, c.xy, b.y, first, rows, s)
                 : pnPcfAddRowsPlane(pnDepthMap, origin, size, receiver, c.xy, b.y, first, rows, s);
    }
    float ratio = !area ? 0.0 : (p.x % 2 == 1) ? pnPcfBlockerMean(s) : pnPcfOccludedFraction(s);
    imageStore(pnResult, p, vec4(s.occluders, s.depthSum, s.texels, ratio));
    return;
  }
  if (b.w == 2.0) {
    PnArea area = pnRegionArea(a.xy, a.z, textureSize(pnDepthMap, 0).x);
    vec3 receiver = vec3(a.xy, b.x);
    PnPcf s = pnPcfZero();
    if (rows <= 0) {
      s = pnPcfAreaPlane(pnDepthMap, area, receiver, vec2(0.0), b.y);
    } else {
      int height = textureSize(pnDepthMap, 0).y;
      for (int first = 0; first < height; first += rows)
        s = pnPcfAddAreaRowsPlane(pnDepthMap, area, receiver, vec2(0.0), b.y, first, rows, s);
    }
    float ratio = (p.x % 2 == 1) ? pnPcfBlockerMean(s) : pnPcfOccludedFraction(s);
    imageStore(pnResult, p, vec4(s.occluders, s.depthSum, s.texels, ratio));
    return;
  }
  PnPcf s;
  if (rows <= 0) {
    // The whole window: every other query through the plane's form with a flat plane (the same sums).
    s = (p.x % 2 == 1) ? pnPcfWindowPlane(pnDepthMap, origin, size, vec3(vec2(origin), b.x), vec2(0.0), b.y)
                       : pnPcfWindow(pnDepthMap, origin, size, b.x, b.y);
  } else {
    s = pnPcfZero();
    int height = textureSize(pnDepthMap, 0).y;
    for (int first = 0; first < height; first += rows)
      s = pnPcfAddRows(pnDepthMap, origin, size, b.x, b.y, first, rows, s);
  }
  imageStore(pnResult, p, vec4(s.occluders, s.depthSum, s.texels, 0.0));
}
