// uniform_block.h — one declaration of a uniform block for both sides of a
// pass: in GLSL a std140 block at its binding, in C++ (runner/gl/std140.h) a
// struct of the same layout. Valid as GLSL and as C++: only comments and
// guarded #defines. A pass's shared header (glsl/passes/<pass>.h) writes
//
//   PN_UNIFORM_BLOCK(PnBlurPassParams, PN_BLUR_PARAMS_BINDING)
//     ivec2 axis;
//     int radius;
//   PN_END_UNIFORM_BLOCK(pnParams)
//
// with only std140-safe members (int, float, ivec2, vec2, ivec4, vec4, mat4,
// arrays of vec4) and arrays of vec2 through PN_VEC2_ARRAY(name, count) (std140
// pads each element to 16 bytes, so C++ gets a padded element type), and the
// runner static_asserts the struct's size and offsets.

#ifndef PENUMBRA_UNIFORM_BLOCK_H
#define PENUMBRA_UNIFORM_BLOCK_H

#ifdef __cplusplus
#define PN_UNIFORM_BLOCK(NAME, BINDING) struct alignas(16) NAME { static constexpr unsigned binding = BINDING;
#define PN_END_UNIFORM_BLOCK(INSTANCE) };
#define PN_VEC2_ARRAY(NAME, COUNT) vec2_element NAME[COUNT];
#else
#define PN_UNIFORM_BLOCK(NAME, BINDING) layout(std140, binding = BINDING) uniform NAME {
#define PN_END_UNIFORM_BLOCK(INSTANCE) } INSTANCE;
#define PN_VEC2_ARRAY(NAME, COUNT) vec2 NAME[COUNT];
#endif

#endif  // PENUMBRA_UNIFORM_BLOCK_H
