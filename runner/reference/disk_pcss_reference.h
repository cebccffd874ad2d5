// CPU reference for the PCSS calls that sample disks — pnPoissonPcss (poisson_pcss.glsl) and
// pnVogelPcss (vogel_pcss.glsl) — written from their definition in double, not from the shaders:
// the search disk of PCSS's search width (blockers at the near plane) around the receiver (u, v);
// its samples' texels below the threshold t(q) = dP − bias + g · (q + ½ − (u, v)) (g the receiver
// plane, 0 without one; a non-finite texel, or a sample outside the map, never occludes); no
// blocker: lit; else the filter disk's diameter c · the penumbra of Eq. (1) at the blocker mean
// (LightModel), and visibility = 1 − occluders / samples over the filter disk.
//
// The GPU decides in float: each sample carries the error of its float position (texels, per
// axis), and reads every texel within it; a blocker search whose occluders or depths that leaves
// open makes the receiver ambiguous (its mean is not known); the filter's open samples make the
// visibility an interval.
#pragma once

#include <functional>

#include "core/image.h"
#include "scene/light_model.h"

namespace pn {

struct DiskSamplePosition {
  double x = 0.0, y = 0.0;  // texels
  double error = 0.0;       // texels, per axis, a GPU's float position may be off by
};

// Occluders and their depth sum over a disk's samples, as bounds (open samples counted both ways).
struct DiskBounds {
  long occluders_lo = 0, occluders_hi = 0;
  double depth_sum_lo = 0.0, depth_sum_hi = 0.0;
  long samples = 0;    // every sample taken, those outside the map included
  long ambiguous = 0;  // samples whose verdict or depth their position error leaves open
};
// `threshold` t = dP − bias; texel q against t + g · (q + ½ − centre); `tie`: the fraction of |t| +
// |g.x Δx| + |g.y Δy| within which a texel's comparison may go either way (0: exact).
DiskBounds disk_bounds(const Image& depth, const std::vector<DiskSamplePosition>& samples, double threshold,
                       double gradient_x, double gradient_y, double centre_x, double centre_y, double tie);

struct DiskPcssReceiver {
  double u = 0.0, v = 0.0, depth = 0.0;       // texels, linear light depth
  double gradient_x = 0.0, gradient_y = 0.0;  // the receiver plane (light depth per texel)
};
// The samples of a disk of `diameter` around `centre` (texels): the call's layout with each
// position's float error, for a diameter known to within `diameter_error` (texels).
using DiskLayout = std::function<std::vector<DiskSamplePosition>(double centre_x, double centre_y, double diameter,
                                                                 double diameter_error)>;
struct DiskPcssResult {
  bool ambiguous = false;                           // the blocker search left open: no reference
  double visibility_lo = 1.0, visibility_hi = 1.0;  // the filter's open samples occluding, not
};
DiskPcssResult disk_pcss_reference(const Image& depth, const LightModel& light, const DiskPcssReceiver& receiver,
                                   double bias, double filter_scale, const DiskLayout& blocker_disk,
                                   const DiskLayout& filter_disk);

}  // namespace pn
