#include "../../outside.glsl"
float m() { return 0.0; }
