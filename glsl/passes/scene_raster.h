// scene_raster.h — what every scene raster pass (shadow_depth, gbuffer,
// surface) shares with runner/pass_runners/scene_draw.cpp, the one draw path that
// feeds them: the vertex attribute of world positions and the colour output
// (the float target, colour attachment 0). Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_SCENE_RASTER_H
#define PENUMBRA_PASSES_SCENE_RASTER_H

#define PN_SCENE_POSITION_LOCATION 0  // in vec3: world position, one per triangle corner
#define PN_SCENE_TARGET_LOCATION 0    // out vec4: the pass's float target

#endif  // PENUMBRA_PASSES_SCENE_RASTER_H
