// A scene worked by hand for the physical reference's tests: the ground slab
// and one 2 x 1 x 2 table top floating at heights 9 to 10 above the origin,
// under a square light of width 2 at height 20 (4 x 4 samples: offsets
// -0.75, -0.25, 0.25, 0.75 in x and z).
#pragma once

#include <cmath>

#include "scene/scene.h"

namespace pn::test {

inline Scene table_scene(int map_size = 64, double light_width = 2.0) {
  Scene scene;
  scene.name = "table";
  scene.boxes = {{{-10.0f, -1.0f, -10.0f}, {10.0f, 0.0f, 10.0f}}, {{-1.0f, 9.0f, -1.0f}, {1.0f, 10.0f, 1.0f}}};
  scene.light = {light_width, 1.0, 40.0, 60.0 * 3.14159265358979 / 180.0, map_size};
  scene.light_position = {0.0f, 20.0f, 0.0f};
  return scene;
}

}  // namespace pn::test
