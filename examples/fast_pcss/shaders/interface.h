// interface.h — the example's bindings and uniform locations, written once:
// main.cpp includes it as C++, and every shader gets it pasted after its
// #version line (valid GLSL and C++: #defines only).

#ifndef EXAMPLE_SHADER_INTERFACE_H
#define EXAMPLE_SHADER_INTERFACE_H

// Vertex input of the raster passes: world position.
#define EX_POSITION_ATTRIBUTE 0

// Uniform locations of the raster passes (shadow_depth.*, lit.*).
#define EX_LIGHT_VIEW_LOCATION 0             // mat4
#define EX_LIGHT_PROJECTION_LOCATION 1       // mat4
#define EX_CAMERA_VIEW_PROJECTION_LOCATION 2 // mat4
#define EX_CAMERA_POSITION_LOCATION 3        // vec3, world
#define EX_LIGHT_POSITION_LOCATION 4         // vec3, world: the area light's centre
#define EX_ALBEDO_LOCATION 5                 // vec3
#define EX_AMBIENT_LOCATION 6                // float
#define EX_BIAS_LOCATION 7                   // float, light-depth units
#define EX_NORMAL_OFFSET_LOCATION 8          // float, shadow-map texels
#define EX_LIGHT_LOCATION 9                  // PnLight: its 6 floats at locations 9..14, in member order

// lit.frag: its inputs (texture units) and its two colour outputs.
#define EX_LIT_MIP_BINDING 0           // the min/max mip chain (RGBA32F, all levels)
#define EX_LIT_SAMPLE_TABLE_BINDING 1  // the 21x8 RG32F sample table
#define EX_LIT_SHADOW_MAP_BINDING 2    // the shadow map the chain is of (its texels)
#define EX_LIT_COLOUR_OUTPUT 0         // RGBA32F: the lit colour
#define EX_LIT_VISIBILITY_OUTPUT 1     // R32F: the visibility Fast PCSS returned

// mip_build.comp: one level per dispatch.
#define EX_MIP_SHADOW_MAP_BINDING 0    // texture unit: the R32F shadow map
#define EX_MIP_READ_BINDING 1          // texture unit: the chain, read at the level below
#define EX_MIP_WRITE_IMAGE 0           // image unit: the chain at the level being written
#define EX_MIP_LEVEL_LOCATION 0        // int
#define EX_MIP_LIGHT_PROJECTION_LOCATION 1  // mat4: mip_from_depth_buffer.glsl only
#define EX_MIP_GROUP_SIZE 8            // 8 x 8 invocations a work group

#endif  // EXAMPLE_SHADER_INTERFACE_H
