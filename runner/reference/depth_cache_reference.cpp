#include "reference/depth_cache_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pn {

float depth_cache_compose_reference(float static_depth, float dynamic_depth) {
  const float far = std::numeric_limits<float>::infinity();
  const float s = std::isfinite(static_depth) ? static_depth : far;
  const float d = std::isfinite(dynamic_depth) ? dynamic_depth : far;
  return std::min(s, d);
}

Image depth_cache_compose_reference(const Image& static_map, const Image& dynamic_map) {
  Image out(static_map.width, static_map.height, 1);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.at(x, y) = depth_cache_compose_reference(static_map.at(x, y), dynamic_map.at(x, y));
  return out;
}

float depth_cache_visibility_reference(float composed, float receiver_depth, float bias) {
  const float threshold = receiver_depth - bias;  // float, as the shader rounds it
  return composed < threshold ? 0.0f : 1.0f;      // NaN threshold: false, lit
}

}  // namespace pn
