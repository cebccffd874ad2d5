// light_fields.h — light_model.glsl's PnLight as the fields of a pass's
// uniform block, written once for every block that carries the light
// (pcss_params.h, pcss_regions_query.h, savsm_params.h, light_model_query.h,
// gbuffer.h) and set once on the C++ side (runner/scene/light_block.h).
// Valid as GLSL and as C++; one line each, since Mesa rejects `\` continuations.

#ifndef PENUMBRA_PASSES_LIGHT_FIELDS_H
#define PENUMBRA_PASSES_LIGHT_FIELDS_H

// Six floats, in PnLight's order: width, near, near-plane width, N, spread, texel world width.
#define PN_LIGHT_FIELDS float lightWidth; float lightNear; float lightNearPlaneWidth; float mapSize; float lightSpread; float lightTexelWorld;

// GLSL: the PnLight of a block instance that holds PN_LIGHT_FIELDS.
#define PN_LIGHT_FROM_FIELDS(block) PnLight(block.lightWidth, block.lightNear, block.lightNearPlaneWidth, block.mapSize, block.lightSpread, block.lightTexelWorld)

#endif  // PENUMBRA_PASSES_LIGHT_FIELDS_H
