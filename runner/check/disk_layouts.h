// Where the disk calls' samples lie and how far a GPU's float position of each may be off: the
// bounds the vogel_pcss and exports checks give the CPU's references (disk_pcss_reference.h,
// vogel_pcss_reference.h) so that a float rounding never reads as a verdict.
#pragma once

#include <vector>

#include "reference/disk_pcss_reference.h"
#include "reference/vogel_pcss_reference.h"
#include "sampling/sample_table_generator.h"

namespace pn {

inline constexpr double kFloatUnit = 1.0 / 16777216.0;  // u = 2^-24
inline constexpr double kTrigError = 1.0 / 2048.0;      // |sin, cos error| on [-π, π] (Vulkan's precision table)

// Texels, per axis, Vogel sample k's float position may be off by (sin and cos, the turn's
// arithmetic, the disk's scale), for a turn known exactly.
double vogel_position_error(const VogelPcssQuery& q, int k);
// The float error of the interleaved gradient noise at (x, y) (the pixel's centre), in turns.
double vogel_noise_bound(double x, double y);

// pnPoissonPcss's samples: c + (s / 2) R o_k for the first `count` points of `disk` (rotation (cos,
// sin)); `trig`: the absolute error of that cos and sin (0 when the block gives them; kTrigError when
// the shader takes them of an angle, pnPoissonRotation).
DiskLayout poisson_layout(const std::vector<Sample>& disk, int count, double rotation_cos, double rotation_sin,
                          double trig = 0.0);
// pnVogelPcss's samples for the pixel (px, py): Vogel's layout turned by the pixel's noise.
DiskLayout vogel_layout(int count, int px, int py);

}  // namespace pn
