// glsl/cascades.h as C++: the split, enlargement, sphere and snap formulas
// that the shaders use, from the same text, evaluated with glm's GLSL-like
// scalars and vectors in float — so the runner fits its cascades to exactly
// the splits a shader would compute.
#pragma once

#include <glm/glm.hpp>

namespace pn::cascade_math {
using namespace glm;
#define PN_CASCADE_FUNCTION inline
#include <cascades.h>
}  // namespace pn::cascade_math
