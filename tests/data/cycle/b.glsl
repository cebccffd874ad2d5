float b() { return 2.0; }
#include "a.glsl"
