// receiver_plane_query.h — what passes/receiver_plane_query.comp and its
// runner side (runner/pass_runners/receiver_plane_pass.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_RECEIVER_PLANE_QUERY_H
#define PENUMBRA_PASSES_RECEIVER_PLANE_QUERY_H

// sampler2D, RGBA32F query images: G-buffer entries (u, v, d, valid) of the receiver and its four
// neighbours, then (maxSlope, origin x, origin y, size x) and (size y, gradient x, gradient y, 0).
#define PN_RECEIVER_PLANE_QUERY_CENTRE_BINDING 1
#define PN_RECEIVER_PLANE_QUERY_LEFT_BINDING 2
#define PN_RECEIVER_PLANE_QUERY_RIGHT_BINDING 3
#define PN_RECEIVER_PLANE_QUERY_BELOW_BINDING 4
#define PN_RECEIVER_PLANE_QUERY_ABOVE_BINDING 5
#define PN_RECEIVER_PLANE_QUERY_F_BINDING 6
#define PN_RECEIVER_PLANE_QUERY_G_BINDING 7
// image2D, rgba32f: (pnReceiverPlaneFromNeighbours, pnReceiverPlaneRange with the query's gradient)
#define PN_RECEIVER_PLANE_QUERY_RESULT_IMAGE 0
// image2D, rgba32f: (pnReceiverPlaneThreshold at the rectangle's last texel, pnReceiverPlaneThresholdRange
// over it, 0), the threshold the receiver's depth, the plane the query's gradient about the receiver
#define PN_RECEIVER_PLANE_QUERY_THRESHOLD_IMAGE 8

#endif  // PENUMBRA_PASSES_RECEIVER_PLANE_QUERY_H
