// The points a square area light is sampled at by the physical reference (the
// GPU pass and its CPU reference take them from here): the centres of a
// regular samples_per_side x samples_per_side grid of equal cells covering the
// light, in its own plane (the light view's x and y axes, world x/z for the
// scenes' downward light), centred on Scene::light_position. Deterministic:
// stratified without jitter, so a result depends on nothing but its inputs.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace pn {

inline constexpr int kMaxSamplesPerSide = 64;

// Throws Error unless 1 <= samples_per_side <= kMaxSamplesPerSide. A light of
// width 0 gives samples_per_side^2 copies of its centre (one hard shadow, as
// many times). Row-major: sample (i, j) is element j * samples_per_side + i.
std::vector<glm::vec3> light_sample_points(const Scene& scene, int samples_per_side);

}  // namespace pn
