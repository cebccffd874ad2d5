// CPU definition of glsl/depth_cache.glsl (seed 001): the composition of a
// static and a dynamic map and the shadow test against it, written from the
// definition (SPEC §3, §5), not from the shader.
#pragma once

#include "core/image.h"

namespace pn {

// min of the two depths, each non-finite one (NaN, ±Inf: no occluder) taken as +Inf.
float depth_cache_compose_reference(float static_depth, float dynamic_depth);
// The composition of two maps of the same size, texel by texel.
Image depth_cache_compose_reference(const Image& static_map, const Image& dynamic_map);
// 0 (in shadow) when the composed depth lies strictly in front of the receiver's depth less the
// bias (the threshold rounded to float, as a shader computes it), 1 otherwise.
float depth_cache_visibility_reference(float composed, float receiver_depth, float bias);

}  // namespace pn
