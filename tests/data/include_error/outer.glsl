// A module whose included file has a compile error on line 4.
#include "inner.glsl"
float outer() { return inner(); }
