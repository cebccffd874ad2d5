// The GLSL types a shared uniform block (glsl/passes/uniform_block.h) may
// hold, as C++ types of std140's size and alignment, in pn::glsl: a pass's
// runner side includes its shared header inside that namespace,
//
//   namespace pn::glsl {
//   #include "passes/blur_bindings.h"
//   }
//
// and static_asserts the block's size and member offsets (PN_STD140_*).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace pn::glsl {

struct alignas(8) ivec2 {
  std::int32_t x = 0, y = 0;
};
struct alignas(8) vec2 {
  float x = 0, y = 0;
};
// An element of a vec2 array in a std140 block (PN_VEC2_ARRAY): std140 rounds its stride up to 16.
struct alignas(16) vec2_element {
  float x = 0, y = 0;
};
struct alignas(16) ivec4 {
  std::int32_t x = 0, y = 0, z = 0, w = 0;
};
struct alignas(16) vec4 {
  float x = 0, y = 0, z = 0, w = 0;
};
struct alignas(16) mat4 {
  float m[16] = {};  // column-major, as glm and GLSL store it
};
static_assert(sizeof(ivec2) == 8 && sizeof(vec4) == 16 && sizeof(mat4) == 64, "std140 base types");

inline mat4 std140_mat4(const glm::mat4& m) {
  mat4 out;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out.m[c * 4 + r] = m[c][r];
  return out;
}

inline vec4 std140_vec4(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

}  // namespace pn::glsl

// A shared block's layout as std140 lays it out: its size (rounded up to 16, as
// the buffer is allocated) and one member's offset.
#define PN_STD140_SIZE(BLOCK, BYTES) static_assert(sizeof(BLOCK) == (BYTES), #BLOCK ": std140 size")
#define PN_STD140_OFFSET(BLOCK, MEMBER, BYTES) \
  static_assert(offsetof(BLOCK, MEMBER) == (BYTES), #BLOCK "." #MEMBER ": std140 offset")
