// vulkan_interface.h — the example's register plan and its frame block, written once: main.cpp includes
// it as C++, the GLSL shaders and shade.hlsl include it (#defines only: valid in all three).
#ifndef EXAMPLE_VULKAN_INTERFACE_H
#define EXAMPLE_VULKAN_INTERFACE_H

// Set 0 of every pipeline of the example. Binding 0: the frame block (a uniform buffer, HLSL b0).
#define EX_FRAME_BINDING 0
// The shading pass (shade.comp, shade.hlsl): the G-buffer, the shadow map's structures, the outputs.
// On the HLSL route a texture at binding N is register tN, an image uN, and the one sampler s9.
#define EX_SHADE_RECEIVERS 1     // RGBA32F: (u, v in shadow-map texels, linear light depth, 1: drawn)
#define EX_SHADE_WORLD 2         // RGBA32F: world position, albedo index (0 ground, 1 model)
#define EX_SHADE_NORMAL 3        // RGBA32F: the face normal, turned toward the camera
#define EX_SHADE_SHADOW_MAP 4    // R32F: linear light depth, +Inf where nothing was drawn
#define EX_SHADE_MIP 5           // RGBA32F: minmax_mip.glsl's chain of the map, all levels
#define EX_SHADE_SAMPLE_TABLE 6  // RG32F: the 21x8 sample table
#define EX_SHADE_VISIBILITY 7    // image, r32f: what pnFastPcss returned
#define EX_SHADE_LIT 8           // image, rgba32f: the lit colour
#define EX_SHADE_SAMPLER 9       // HLSL only: one point-clamp SamplerState (the modules only fetch)
#define EX_SHADE_GROUP_SIZE 8

// The frame block, every member a vec4 or a mat4 (one layout in std140, an HLSL cbuffer and C++):
// EX_FRAME_MEMBERS(MAT4, VEC4) lists them in order for each language to declare.
//   exLightView, exLightProjection     the light's view and OpenGL-convention projection
//                                      (pnLightProject reads x, y and w only)
//   exLightRaster, exCameraRaster      the same projection with Vulkan's [0, 1] depth (x, y, w the
//                                      same rows), and the camera's view-projection likewise
//   exCameraPosition, exLightPosition  xyz, world
//   exLight0, exLight1                 PnLight: (width, near, nearPlaneWidth, mapSize),
//                                      (spread, texelWorld, depth bias, normal offset in texels)
//   exShading                          (ambient, 0, 0, 0)
//   exGroundAlbedo, exModelAlbedo, exSky  rgb
#define EX_FRAME_MEMBERS(MAT4, VEC4)                                                          \
  MAT4(exLightView) MAT4(exLightProjection) MAT4(exLightRaster) MAT4(exCameraRaster)          \
  VEC4(exCameraPosition) VEC4(exLightPosition) VEC4(exLight0) VEC4(exLight1) VEC4(exShading) \
  VEC4(exGroundAlbedo) VEC4(exModelAlbedo) VEC4(exSky)

#endif  // EXAMPLE_VULKAN_INTERFACE_H
