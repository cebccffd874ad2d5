// The truth's points on the square area light (SPEC §4.9): an S x S grid of
// equal cells over the light, in its own plane (the light view's x and y axes,
// as scene/light_samples.h), centred on Scene::light_position, one point per
// cell at a jittered place inside it. The jitter comes from an integer hash of
// (seed, pixel, sample, axis), so it is deterministic, differs from pixel to
// pixel (the noise is not the same pattern everywhere) and does not depend on
// threads, screen size or the order of evaluation.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace pn {

// The jitter of sample `sample` of pixel (x, y) along `axis` (0: the light's
// x, 1: its y), in [0, 1) with 24 random bits.
double sample_jitter(std::uint32_t seed, int x, int y, int sample, int axis);

// The light's world axes and centre, for placing points on it.
struct LightFrame {
  glm::dvec3 centre, right, up;  // right, up: unit axes of the light's plane
  double width = 0;
};
LightFrame light_frame(const Scene& scene);

// The S x S jittered points of pixel (x, y); sample (i, j) is element
// j · S + i and lies in cell [i/S, (i+1)/S) x [j/S, (j+1)/S) of the light
// (in fractions of its width, from its corner at −right, −up). A light of
// width 0 gives S² copies of its centre. S is not checked here (the caller
// validates it).
std::vector<glm::dvec3> jittered_light_samples(const LightFrame& light, int samples_per_side, std::uint32_t seed, int x,
                                               int y);

}  // namespace pn
