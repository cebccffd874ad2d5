// receiver_plane_query.comp — receiver_plane.glsl over a batch of receivers.
// Query k: the receiver's G-buffer entry and its left, right, below and above
// neighbours', (maxSlope, origin, size.x), (size.y, gradient, 0).
// Result k: (the gradient from the neighbours, the plane's range over the
// rectangle [origin, origin + size) with the query's gradient); threshold result k: (the plane's
// threshold at the rectangle's last texel, its threshold range over the rectangle, 0), the
// threshold the receiver's depth.
//   bindings: receiver_plane_query.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "receiver_plane_query.h"
#include "receiver_plane.glsl"

layout(binding = PN_RECEIVER_PLANE_QUERY_CENTRE_BINDING) uniform sampler2D pnCentre;
layout(binding = PN_RECEIVER_PLANE_QUERY_LEFT_BINDING) uniform sampler2D pnLeft;
layout(binding = PN_RECEIVER_PLANE_QUERY_RIGHT_BINDING) uniform sampler2D pnRight;
layout(binding = PN_RECEIVER_PLANE_QUERY_BELOW_BINDING) uniform sampler2D pnBelow;
layout(binding = PN_RECEIVER_PLANE_QUERY_ABOVE_BINDING) uniform sampler2D pnAbove;
layout(binding = PN_RECEIVER_PLANE_QUERY_F_BINDING) uniform sampler2D pnQueryF;
layout(binding = PN_RECEIVER_PLANE_QUERY_G_BINDING) uniform sampler2D pnQueryG;
layout(rgba32f, binding = PN_RECEIVER_PLANE_QUERY_RESULT_IMAGE) writeonly uniform image2D pnResult;
layout(rgba32f, binding = PN_RECEIVER_PLANE_QUERY_THRESHOLD_IMAGE) writeonly uniform image2D pnThresholds;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 centre = texelFetch(pnCentre, p, 0);
  vec4 f = texelFetch(pnQueryF, p, 0), g = texelFetch(pnQueryG, p, 0);
  vec2 gradient = pnReceiverPlaneFromNeighbours(centre, texelFetch(pnLeft, p, 0), texelFetch(pnRight, p, 0),
                                                texelFetch(pnBelow, p, 0), texelFetch(pnAbove, p, 0), f.x);
  ivec2 origin = ivec2(f.yz), size = ivec2(int(f.w), int(g.x));
  vec2 range = pnReceiverPlaneRange(centre.xyz, g.yz, origin, size);
  imageStore(pnResult, p, vec4(gradient, range));
  float threshold = pnReceiverPlaneThreshold(centre.z, g.yz, centre.xy, origin + size - 1);
  vec2 thresholds = pnReceiverPlaneThresholdRange(centre.z, g.yz, centre.xy, origin, origin + size);
  imageStore(pnThresholds, p, vec4(threshold, thresholds, 0.0));
}
