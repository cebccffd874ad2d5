// CPU reference for glsl/backprojection.glsl, written from its definition in
// double: the shadow map is a surface — texel (i, j) of depth d a flat patch,
// its square at depth d, joined to each 4-neighbour whose depth is within `gap`
// texel widths by a wall on their shared edge spanning the two depths; a larger
// step is a silhouette, its wall reaching `thickness` · (dP - d) below d (0:
// open). The light is backprojection.h's side × side
// samples l of its square. For each sample, the ray from the receiver to the
// light point (an area light: the point l · w_L on the light's square at depth 0;
// the sun: the direction l · S per unit of depth toward the light) is followed in
// the light's 3-D frame, and it is blocked when it crosses a patch or a wall in
// front of the receiver (depth < dP - bias) — brute force over the texels and
// every sample, each crossing solved from the ray's projection (not from the
// shader's windows or its traversal). visibility = 1 - blocked / side².
//
// The GPU decides in float: a sample whose verdict would change if every texel
// grew or shrank by `margin` texels or every depth moved by `depth_margin` · dP
// is ambiguous; the visibility is an interval, its ends counting the ambiguous
// samples lit or blocked.
#pragma once

#include "core/image.h"
#include "scene/light_model.h"

namespace pn {

struct BackprojectionSamplePoint {
  float x = 0.0f, y = 0.0f;  // in [-1/2, 1/2]²: the fraction of the light's width (or spread)
};

// Light sample k of side × side, placed as backprojection.glsl places it (backprojection.h).
BackprojectionSamplePoint backprojection_sample(int k, int side);

struct BackprojectionBounds {
  double visibility_lo = 1.0, visibility_hi = 1.0;  // the ambiguous samples blocked, lit
  int ambiguous = 0;                                 // samples within the margins of a verdict
};

// The receiver (u, v) in texels, `depth` its linear light depth; `map` the N×N linear light depth
// (non-finite: no occluder), N = light.map_size. A receiver at a non-positive or non-finite
// depth is lit.
BackprojectionBounds backprojection_reference(const Image& map, const LightModel& light, double u, double v,
                                              double depth, double bias, int side, double gap, double thickness,
                                              double margin = 1e-3, double depth_margin = 1e-5);

// The same samples against slabs (issue 42): texel (i, j) of `map` at depth d is solid from d down
// to `second`'s depth there (non-finite: down to the receiver; not past d: a flat square at d),
// the column of its square in the light's frame; a sample is blocked when its ray is inside some
// texel's column at a depth between d and min(its second depth, depth - bias) — each ray solved
// against each column (where it crosses the square's edges), not through patches and walls.
// The margins as above.
BackprojectionBounds backprojection_slab_reference(const Image& map, const Image& second, const LightModel& light,
                                                   double u, double v, double depth, double bias, int side,
                                                   double margin = 1e-3, double depth_margin = 1e-5);

}  // namespace pn
