// The city (fixtures/city_scenes.h): buildings, poles and models as one
// static scene lit by the sun (Scene::sun), its camera at a frame of its path.
#pragma once

#include <string>

#include "city_scenes.h"
#include "scene/scene.h"

namespace pn {

// The fixture called `name`; throws Error listing the names. Null from the
// `find_…_or_null` form, so that a caller can try the other scene kinds first.
const fixtures::CitySceneFixture* find_city_scene_fixture_or_null(const std::string& name);

// The city with its sun's whole-scene map N×N (light_by_sun) and the camera at frame 0.
// Throws Error for N < 2 or a model file that cannot be read.
Scene make_city_scene(const fixtures::CitySceneFixture& fixture, int shadow_map_size);

// The camera of the city's path at `frame` (>= 0): a step along the street and a turn per frame.
SceneCamera city_camera(int frame);

}  // namespace pn
