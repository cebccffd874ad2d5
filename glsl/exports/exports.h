// exports.h — the bindings of the export entries the runner also runs (the exports
// check: runner/check/exports_check.cpp). Valid as GLSL and as C++.
//
// Why an entry: SPIR-V keeps only what an entry point reaches, so `penumbra bundle X.glsl
// --target hlsl|msl` translates exports/X.comp, which makes the module's public call once per
// receiver of a receiver image (exports/X_call.glsl: every overload, selected per receiver): the
// export then holds the call and everything it calls, with the parameters' names. X.frag makes the
// same call in a fragment shader. The bindings are an example; an engine calls the exported
// function from its own shader with its own resources.
//
// PN_EXPORT_ENGINE (defined by `penumbra isa`, docs/isa.md): the call as an engine compiles it —
// the overload docs/integration.md shows, with the module's shipped defaults as constants (only
// the bias and the light from the block) — instead of every overload with settings from the block.

#ifndef PENUMBRA_EXPORTS_EXPORTS_H
#define PENUMBRA_EXPORTS_EXPORTS_H


// Distinct across resource kinds (Vulkan and HLSL compiled back have one namespace a set).
#define PN_EXPORT_VISIBILITY_IMAGE 0  // image2D, r32f: the visibility
#define PN_EXPORT_RECEIVERS_BINDING 1  // sampler2D: (u, v, light depth, 1: with the receiver plane)
#define PN_EXPORT_PLANES_BINDING 2     // sampler2D: (du, dv), light depth per texel
#define PN_EXPORT_DEPTH_MAP_BINDING 3  // sampler2D: the shadow map, linear light depth
#define PN_EXPORT_PARAMS_BINDING 4

#endif  // PENUMBRA_EXPORTS_EXPORTS_H
