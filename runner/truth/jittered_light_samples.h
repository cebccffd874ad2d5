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

// The light's world axes and centre, for placing points on it. A directional light (the
// sun, Scene::sun) has no place: its points lie `distance` from each receiver, inside the
// cone of half-angle theta / 2 around `towards` (tan_half_angle = tan(theta / 2)).
struct LightFrame {
  glm::dvec3 centre, right, up;  // right, up: unit axes of the light's plane (the sun's: its view's x and y)
  double width = 0;
  bool directional = false;
  glm::dvec3 towards{0.0};        // directional: unit vector towards the light
  double tan_half_angle = 0;
  double distance = 0;            // directional: past every triangle of the scene
};
LightFrame light_frame(const Scene& scene);

// Whether a surface of normal `normal` at `position` faces the light's centre (N·L > 0).
bool faces_light(const LightFrame& light, const glm::dvec3& position, const glm::dvec3& normal);

// The S x S jittered points of pixel (x, y); sample (i, j) is element
// j · S + i and lies in cell [i/S, (i+1)/S) x [j/S, (j+1)/S) of the light
// (in fractions of its width, from its corner at −right, −up). A light of
// width 0 gives S² copies of its centre. S is not checked here (the caller
// validates it).
std::vector<glm::dvec3> jittered_light_samples(const LightFrame& light, int samples_per_side, std::uint32_t seed, int x,
                                               int y);

// The directional light's S x S jittered points for pixel (x, y) seen from `receiver`: the
// square's cells mapped onto the sun's disc by Shirley and Chiu's concentric map (each cell
// to an equal-area piece of the disc, so the points stay stratified), each at `distance`
// from the receiver along its direction.
std::vector<glm::dvec3> jittered_sun_points(const LightFrame& light, int samples_per_side, std::uint32_t seed, int x,
                                            int y, const glm::dvec3& receiver);

}  // namespace pn
