// Drawing a scene's boxes into a float target with depth testing: the one
// raster path that the shadow map, the G-buffer and the surface pass share.
#pragma once

#include "gl/objects.h"
#include "scene/scene.h"

namespace pn {

// Renders every triangle of `scene` with `program` (vertex attribute
// PN_SCENE_POSITION_LOCATION: world position; output PN_SCENE_TARGET_LOCATION,
// glsl/passes/scene_raster.h) into a new size×size float texture of `channels`
// channels cleared to `clear`, nearest surface kept. It binds no resources:
// the caller's PassBindings holds what the program reads for the duration of
// the call (its uniform block at the pass header's binding).
GlObject draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                    const float clear[4]);

}  // namespace pn
