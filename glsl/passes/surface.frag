// surface.frag — what a lit image needs besides visibility: per pixel, the
// albedo of the surface seen (rgb) and max(dot(N, L), 0) (a), N the face
// normal turned toward the camera, L the unit direction to the light's centre.
// The target is cleared to 0, so a pixel that sees nothing reads (0, 0, 0, 0).
//
// N comes from the screen-space derivatives of the world position: both
// neighbours of a 2x2 quad lie on the same triangle's plane (helper
// invocations extrapolate it), so their cross product is the face normal with
// no normal attribute. The ground is told from the boxes by position: a point
// inside its box, widened by PN_SURFACE_GROUND_TOLERANCE world units (boxes
// stand on it and touch it only along their bottom edges).
// Cost: a few ALU operations per fragment, no texture reads.
// The parameter block (shared with surface.vert), its binding and the locations: surface.h.
//
// Options: PN_SURFACE_GROUND_TOLERANCE (world units, default 1e-3).

#ifndef PN_SURFACE_GROUND_TOLERANCE
#define PN_SURFACE_GROUND_TOLERANCE 1e-3
#endif

#include "surface.h"

layout(location = PN_SURFACE_WORLD_LOCATION) in vec3 pnWorld;
layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnSurface;

void main() {
  vec3 normal = cross(dFdx(pnWorld), dFdy(pnWorld));
  if (dot(normal, pnParams.cameraPosition.xyz - pnWorld) < 0.0) normal = -normal;
  vec3 toLight = pnParams.lightPosition.xyz - pnParams.lightPosition.w * pnWorld;
  // A face seen exactly edge-on (or a fragment at the light) has no direction: 0, never NaN.
  float lengths = length(normal) * length(toLight);
  float cosine = lengths > 0.0 ? dot(normal, toLight) / lengths : 0.0;
  float tolerance = float(PN_SURFACE_GROUND_TOLERANCE);
  bool ground = all(greaterThanEqual(pnWorld, pnParams.groundLo.xyz - tolerance)) &&
                all(lessThanEqual(pnWorld, pnParams.groundHi.xyz + tolerance));
  vec3 albedo = ground ? pnParams.groundAlbedo.rgb : pnParams.boxAlbedo.rgb;
  pnSurface = vec4(albedo, clamp(cosine, 0.0, 1.0));
}
