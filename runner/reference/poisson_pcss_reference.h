// CPU reference for glsl/poisson_pcss.glsl, written from its definition in
// double: sample k of a disk of diameter s around centre c lies at
//   p_k = c + (s / 2) (r.x o.x - r.y o.y, r.y o.x + r.x o.y),
// reads texel floor(p_k) when p_k is inside the map (nothing otherwise), and
// occludes when that texel's depth d is finite and d < dP - bias. The raw
// map is read (NaN and ±Inf allowed), nothing is sanitised beforehand.
#pragma once

#include <vector>

#include "core/image.h"
#include "sampling/sample_table_generator.h"

namespace pn {

struct PoissonPcssQuery {
  double centre_x = 0.0, centre_y = 0.0;  // texels, continuous
  double diameter = 0.0;                  // texels
  double receiver_depth = 0.0, bias = 0.0;
  int count = 0;                          // clamped to [0, points.size()]
  double rotation_x = 1.0, rotation_y = 0.0;  // (cos, sin); (1, 0): none
};

struct PoissonPcssSums {
  long occluders = 0;
  double depth_sum = 0.0;
  long samples = 0;  // every sample taken, those outside the map included

  double blocker_mean() const { return occluders > 0 ? depth_sum / static_cast<double>(occluders) : 0.0; }
  double occluded_fraction() const {
    return samples > 0 ? static_cast<double>(occluders) / static_cast<double>(samples) : 0.0;
  }
};

struct PoissonPcssPosition {
  double x = 0.0, y = 0.0;  // texels
};

// Where the sample at unit-disk `offset` lies (texels).
PoissonPcssPosition poisson_pcss_position(const PoissonPcssQuery& query, const Sample& offset);

PoissonPcssSums poisson_pcss_reference(const Image& depth, const std::vector<Sample>& points,
                                       const PoissonPcssQuery& query);

}  // namespace pn
