// frame.glsl — the frame block (vulkan_interface.h) as the GLSL shaders declare it: its members global.
#include "vulkan_interface.h"
#define EX_GLSL_MAT4(NAME) mat4 NAME;
#define EX_GLSL_VEC4(NAME) vec4 NAME;
layout(std140, set = 0, binding = EX_FRAME_BINDING) uniform ExFrame { EX_FRAME_MEMBERS(EX_GLSL_MAT4, EX_GLSL_VEC4) };
