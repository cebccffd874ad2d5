// receiver_plane.h — the constants that glsl/receiver_plane.glsl and the C++
// runner share. Valid as GLSL and as C++: only comments and guarded #defines.

#ifndef PENUMBRA_RECEIVER_PLANE_H
#define PENUMBRA_RECEIVER_PLANE_H

// The two steps are taken as parallel — the receiver seen edge-on from the
// light or the camera, or steps too short to tell apart — when the sine of
// the angle between their (du, dv) is below this (0.57°): |det| < it · |a| |b|.
// The steps are float differences of map positions up to a few thousand
// texels (an error of ~1e-4 texels each), so a smaller bound would let
// rounding decide the plane.
#ifndef PN_RECEIVER_PLANE_MIN_SINE
#define PN_RECEIVER_PLANE_MIN_SINE 0.01
#endif

#endif  // PENUMBRA_RECEIVER_PLANE_H
