// Drawing a scene's boxes into a float target with depth testing: the one
// raster path that the shadow map and the G-buffer share.
#pragma once

#include "gl/objects.h"
#include "scene/scene.h"

namespace pn {

// Renders every triangle of `scene` with `program` (vertex attribute 0: world
// position; uniform block `block` at binding 0) into a new size×size float
// texture of `channels` channels cleared to `clear`, nearest surface kept.
GlObject draw_scene(const Context& context, const GlObject& program, const Scene& scene, int size, int channels,
                    const float clear[4], const void* block, std::size_t block_size);

}  // namespace pn
