// The light as the float fields of light_model.glsl's PnLight that a pass's
// uniform block carries (PN_LIGHT_FIELDS, glsl/passes/light_fields.h), set in
// one place.
#pragma once

#include "scene/light_model.h"

namespace pn {

template <class Block>
void set_light_fields(Block& b, const LightModel& light) {
  b.lightWidth = static_cast<float>(light.width);
  b.lightNear = static_cast<float>(light.near_plane);
  b.lightNearPlaneWidth = static_cast<float>(light.near_plane_width());
  b.mapSize = static_cast<float>(light.map_size);
  b.lightSpread = static_cast<float>(light.spread);
  b.lightTexelWorld = static_cast<float>(light.texel_world);
}

}  // namespace pn
