// receiver_plane.h — the constants that glsl/receiver_plane.glsl and the C++
// runner share. Valid as GLSL and as C++: only comments and guarded #defines.

#ifndef PENUMBRA_RECEIVER_PLANE_H
#define PENUMBRA_RECEIVER_PLANE_H

// The steps' Jacobian is singular below this |det| (texels²): the receiver is
// seen edge-on (from the light or the camera) and the plane is not used.
#ifndef PN_RECEIVER_PLANE_MIN_DET
#define PN_RECEIVER_PLANE_MIN_DET 1.0e-6
#endif

#endif  // PENUMBRA_RECEIVER_PLANE_H
